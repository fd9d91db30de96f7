/**
 * The render node's figures (nodes/core/figures.ts) as one drawing in world coordinates: strokes,
 * dots and labels, with widths in output pixels. The editor's overlay, the SVG writer and the PNG
 * painter all draw this same value, so the three agree.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Circle, Color, Vec2 } from '../../nodes/core/values.ts';
import type { View } from '../../nodes/core/view.ts';
import { circleThrough3, invertPoint } from '../../nodes/geometry/circle.ts';
import { autoBase, cayleyGraph } from './cayley.ts';
import { limitSetDfs } from './limit-dfs.ts';

export interface FigureStroke {
  readonly points: readonly Vec2[];
  readonly color: Color;
  /** Pixels. */
  readonly width: number;
}

export interface FigureDot {
  readonly at: Vec2;
  readonly color: Color;
  /** Radius, pixels. */
  readonly r: number;
}

export interface FigureLabel {
  readonly at: Vec2;
  readonly text: string;
  readonly color: Color;
}

export interface FigureLayer {
  readonly strokes: readonly FigureStroke[];
  readonly dots: readonly FigureDot[];
  readonly labels: readonly FigureLabel[];
  /** Why a figure is missing or partial, one line each. */
  readonly notes: readonly string[];
}

export const EMPTY_LAYER: FigureLayer = { strokes: [], dots: [], labels: [], notes: [] };

/** Edge colours by generator pair (sRGB), distinct on light and dark tilings. */
export const GENERATOR_COLOURS: readonly Color[] = [
  [0.95, 0.26, 0.21],
  [0.13, 0.59, 0.95],
  [1, 0.76, 0.03],
  [0.3, 0.69, 0.31],
  [0.61, 0.15, 0.69],
  [1, 0.44, 0],
  [0, 0.74, 0.83],
  [0.91, 0.12, 0.39],
];

const VERTEX: Color = [1, 1, 1];
const ARC_STEPS = 16;

/**
 * The edge from p to q drawn as the hyperbolic geodesic of the clip disk (the Poincaré disk): the
 * circle through p, q and p's mirror image in the clip circle is orthogonal to it; its shorter arc
 * from p to q lies inside. Without a clip disk, or when p, q and the centre are collinear, the
 * straight segment.
 */
export function edgePath(p: Vec2, q: Vec2, clip: Circle | null): Vec2[] {
  const mirror = clip ? invertPoint(clip, p) : null;
  const arc = mirror ? circleThrough3(p, q, mirror) : null;
  if (!arc || arc.r > 1e3 * Math.hypot(q[0] - p[0], q[1] - p[1])) return [p, q];
  const a0 = Math.atan2(p[1] - arc.c[1], p[0] - arc.c[0]);
  let da = Math.atan2(q[1] - arc.c[1], q[0] - arc.c[0]) - a0;
  if (da > Math.PI) da -= 2 * Math.PI;
  if (da < -Math.PI) da += 2 * Math.PI;
  const out: Vec2[] = [p];
  for (let i = 1; i < ARC_STEPS; i++) {
    const t = a0 + (da * i) / ARC_STEPS;
    out.push([arc.c[0] + arc.r * Math.cos(t), arc.c[1] + arc.r * Math.sin(t)]);
  }
  out.push(q);
  return out;
}

/**
 * The figures of the scene for an output of width × height pixels at the scene's view. The Cayley
 * graph's automatic base point is chosen in `baseView` (default: the scene's view): the live
 * overlay passes the document's view while it draws at the view being panned, so the graph's
 * vertices stay on their tiles during a pan instead of sliding with the view.
 */
export function figureLayer(
  scene: Scene,
  width: number,
  height: number,
  baseView: View = scene.view,
): FigureLayer {
  const f = scene.figures;
  if (!f || (f.cayleyDepth <= 0 && !f.limitSetDfs) || width <= 0 || height <= 0) return EMPTY_LAYER;
  const pixelWorld = scene.view.scale / height;
  const strokes: FigureStroke[] = [];
  const dots: FigureDot[] = [];
  const labels: FigureLabel[] = [];
  const notes: string[] = [];
  if (f.limitSetDfs) {
    const dfs = limitSetDfs(scene, { pixelWorld, width, height });
    if (!dfs.ok) notes.push(`Limit set (depth-first): ${dfs.message}`);
    else {
      if (dfs.capped) notes.push(`Limit set (depth-first): ${dfs.capped}`);
      const color = scene.tile.limitColor;
      for (const c of dfs.curves) {
        if (c.length === 1) dots.push({ at: c[0], color, r: 0.75 });
        else strokes.push({ points: c, color, width: 1 });
      }
    }
  }
  if (f.cayleyDepth > 0) {
    const base = f.cayleyBase ?? autoBase({ ...scene, view: baseView }, width / height);
    const g = cayleyGraph(scene, base, { depth: f.cayleyDepth, pixelWorld }, width / height);
    if (!g.ok) notes.push(`Cayley graph: ${g.message}`);
    else {
      if (g.capped) notes.push(`Cayley graph: ${g.capped}`);
      for (const e of g.edges) {
        const gen = g.generators[e.generator];
        const color = GENERATOR_COLOURS[gen.pair % GENERATOR_COLOURS.length];
        const points = edgePath(e.from, e.to, scene.clip);
        strokes.push({ points, color, width: 2 });
        if (e.depth === 0) {
          const [a, b] = [points[(points.length - 1) >> 1], points[points.length >> 1]];
          labels.push({ at: [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], text: gen.name, color });
        }
      }
      for (const v of g.vertices) dots.push({ at: v, color: VERTEX, r: 2.5 });
      dots.push({ at: g.base, color: VERTEX, r: 4.5 });
    }
  }
  return { strokes, dots, labels, notes };
}
