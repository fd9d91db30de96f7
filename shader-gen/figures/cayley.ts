/**
 * The Cayley graph of the scene's group drawn over its tiling (docs/math.md "Cayley graph and
 * depth-first limit set"): the vertex of the tile w(F) is w(p₀), p₀ a base point in the
 * fundamental tile F, and the edge labelled k joins w(p₀) to w(T_k(p₀)) — the centre of the
 * neighbouring tile w T_k(F). Breadth-first over reduced words up to a depth, in float64.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Circle, Vec2 } from '../../nodes/core/values.ts';
import { type AntiMobius, applyMap, compose, IDENTITY } from '../../nodes/geometry/anti-mobius.ts';
import { type FigureGenerator, sceneGenerators } from '../../nodes/geometry/group-generators.ts';
import { prepare } from '../interpret.ts';

export interface CayleyEdge {
  readonly from: Vec2;
  readonly to: Vec2;
  /** The generator (index into `generators`) that leads from `from` to `to`. */
  readonly generator: number;
  /** Steps from the base point to `from`. */
  readonly depth: number;
}

export interface CayleyOptions {
  readonly depth: number;
  /** World units per output pixel: edges shorter than `minEdgePx` pixels are not followed. */
  readonly pixelWorld: number;
  readonly minEdgePx?: number;
  /** Edge cap (default MAX_CAYLEY_EDGES). */
  readonly maxEdges?: number;
}

/** The most edges one Cayley graph draws: beyond it, edges are too dense to read. */
export const MAX_CAYLEY_EDGES = 20_000;

export type CayleyGraph =
  | {
      readonly ok: true;
      readonly base: Vec2;
      readonly vertices: readonly Vec2[];
      readonly edges: readonly CayleyEdge[];
      readonly generators: readonly FigureGenerator[];
      /** Set when the edge cap stopped the enumeration (the graph drawn is the part found). */
      readonly capped?: string;
    }
  | { readonly ok: false; readonly message: string; readonly nodeId?: string };

const GRID = 64;

/**
 * An interior point of the fundamental tile, the same wherever the view is as long as that part of
 * the tile is in it (so the Cayley graph's vertices stay on their tiles while the view pans):
 * 1. over a 64 × 64 grid of the view, the points outside every element's inside (and inside the
 *    clip disk), ranked by their clearance — the distance to the nearest mirror, the clip circle
 *    and the view's edge — weighted by 1 − ρ, ρ the distance from the view centre over the half
 *    diagonal, so that parts of the tile in the middle of the picture come first;
 * 2. from the best few, a local search climbs the clearance without the view's terms (nearest
 *    mirror and clip circle) to its maximum in that part: the centre of the largest disk that fits
 *    in it, which does not depend on the view. The first climb, in rank order, that ends in the
 *    view gives the point (else the first that ends anywhere near); a part with no maximum (the
 *    unbounded outside of a ring of disks) lets the climb run away and is skipped. When every
 *    climb runs away, the best grid point is kept (then the point follows the view).
 */
export function autoBase(scene: Pick<Scene, 'elements' | 'clip' | 'view'>, aspect = 1): Vec2 | null {
  const { elements, kinds } = prepare(scene.elements);
  const { center, scale } = scene.view;
  const hw = (scale * aspect) / 2;
  const hh = scale / 2;
  /** Distance to the nearest mirror and to the clip circle; ≤ 0 outside the fundamental tile. */
  const clearance = (x: number, y: number): number => {
    if (elements.some((e, k) => kinds[k].inside(e, x, y))) return 0;
    let c = Number.POSITIVE_INFINITY;
    if (scene.clip) c = scene.clip.r - Math.hypot(x - scene.clip.c[0], y - scene.clip.c[1]);
    for (let k = 0; k < elements.length; k++) c = Math.min(c, kinds[k].boundaryDistance(elements[k], x, y));
    return c;
  };
  const ranked: { at: Vec2; score: number }[] = [];
  for (let i = 0; i < GRID; i++) {
    for (let j = 0; j < GRID; j++) {
      const x = center[0] - hw + ((i + 0.5) / GRID) * 2 * hw;
      const y = center[1] - hh + ((j + 0.5) / GRID) * 2 * hh;
      const c = clearance(x, y);
      if (c <= 0) continue;
      const edge = Math.min(hw - Math.abs(x - center[0]), hh - Math.abs(y - center[1]));
      const score = Math.min(c, edge) * (1 - Math.hypot(x - center[0], y - center[1]) / Math.hypot(hw, hh));
      if (score > 0) ranked.push({ at: [x, y], score });
    }
  }
  if (ranked.length === 0) return null;
  ranked.sort((a, b) => b.score - a.score);
  const cell = (2 * hh) / GRID;
  const inView = (p: Vec2) => Math.abs(p[0] - center[0]) <= hw && Math.abs(p[1] - center[1]) <= hh;
  /** A climb that leaves this box ran away: the part has no maximum near the view. */
  const near = (p: Vec2) => Math.abs(p[0] - center[0]) <= 8 * hw && Math.abs(p[1] - center[1]) <= 8 * hh;
  let fallback: Vec2 | null = null;
  for (const { at } of ranked.slice(0, CLIMB_STARTS)) {
    const top = climb(at, clearance, cell, near);
    if (top && inView(top)) return top;
    fallback ??= top;
  }
  return fallback ?? ranked[0]!.at;
}

/** Grid points from which autoBase climbs (the best ranked). */
const CLIMB_STARTS = 12;
/** The local search's window: (2·WINDOW + 1)² points h apart around the current point. */
const WINDOW = 3;
const CLIMB_ROUNDS = 300;

/**
 * Local search for the maximum of `f` from `start`: move to the best of the (2·WINDOW + 1)² points
 * spaced h around the current one, halve h when the current one is best, until h < 10⁻¹⁰ of the
 * first step. A window of points in many directions follows the ridges of a minimum of distances,
 * where a compass search stalls. Null when the walk leaves `near` (no maximum there).
 */
function climb(
  start: Vec2,
  f: (x: number, y: number) => number,
  step: number,
  near: (p: Vec2) => boolean,
): Vec2 | null {
  let at: Vec2 = start;
  let value = f(at[0], at[1]);
  let h = step;
  for (let round = 0; round < CLIMB_ROUNDS && h > step * 1e-10; round++) {
    let best = at;
    for (let i = -WINDOW; i <= WINDOW; i++) {
      for (let j = -WINDOW; j <= WINDOW; j++) {
        const p: Vec2 = [at[0] + i * h, at[1] + j * h];
        const v = f(p[0], p[1]);
        if (v > value) {
          value = v;
          best = p;
        }
      }
    }
    if (best === at) h /= 2;
    else {
      at = best;
      if (!near(at)) return null;
    }
  }
  return at;
}

const outside = (clip: Circle | null, p: Vec2) =>
  clip !== null && Math.hypot(p[0] - clip.c[0], p[1] - clip.c[1]) >= clip.r;

/** The Cayley graph up to options.depth steps from the base point (null: autoBase). */
export function cayleyGraph(
  scene: Pick<Scene, 'elements' | 'clip' | 'view'>,
  basePoint: Vec2 | null,
  options: CayleyOptions,
  aspect = 1,
): CayleyGraph {
  const found = sceneGenerators(scene);
  if (!found.ok) return found;
  const { generators } = found;
  const base = basePoint ?? autoBase(scene, aspect);
  if (!base)
    return {
      ok: false,
      message: 'the fundamental tile is not in the view: no base point for the Cayley graph',
    };
  const cap = options.maxEdges ?? MAX_CAYLEY_EDGES;
  const minEdge = (options.minEdgePx ?? 2) * options.pixelWorld;
  // Vertices closer than a hundredth of a pixel are one (words equal in the group, by rounding).
  const eps = options.pixelWorld / 100;
  const key = (p: Vec2) => `${Math.round(p[0] / eps)},${Math.round(p[1] / eps)}`;
  const seen = new Set<string>([key(base)]);
  const edgeKeys = new Set<string>();
  const vertices: Vec2[] = [base];
  const edges: CayleyEdge[] = [];
  // Far outside the view nothing shows: the bound keeps Euclidean (non-shrinking) groups finite.
  const far = options.pixelWorld * 1e4 + 4 * scene.view.scale;
  let level: { map: AntiMobius; at: Vec2; last: number }[] = [{ map: IDENTITY, at: base, last: -1 }];
  for (let depth = 0; depth < options.depth && level.length > 0; depth++) {
    const next: typeof level = [];
    for (const item of level) {
      for (let k = 0; k < generators.length; k++) {
        if (item.last >= 0 && generators[item.last].inverse === k) continue;
        const map = compose(item.map, generators[k].map);
        const at = applyMap(map, base);
        if (!at || !Number.isFinite(at[0]) || !Number.isFinite(at[1])) continue;
        if (outside(scene.clip, at)) continue;
        if (Math.hypot(at[0] - scene.view.center[0], at[1] - scene.view.center[1]) > far) continue;
        const a = key(item.at);
        const b = key(at);
        // One edge per generator pair: w→wT_k and wT_k→w (by T_k⁻¹) are the same edge.
        const ek = `${generators[k].pair}:${a < b ? `${a}|${b}` : `${b}|${a}`}`;
        if (!edgeKeys.has(ek)) {
          edgeKeys.add(ek);
          edges.push({ from: item.at, to: at, generator: k, depth });
          if (edges.length >= cap) {
            return {
              ok: true,
              base,
              vertices,
              edges,
              generators,
              capped: `the Cayley graph stopped at ${cap} edges: lower its depth`,
            };
          }
        }
        if (seen.has(b)) continue;
        seen.add(b);
        vertices.push(at);
        if (Math.hypot(at[0] - item.at[0], at[1] - item.at[1]) >= minEdge) next.push({ map, at, last: k });
      }
    }
    level = next;
  }
  return { ok: true, base, vertices, edges, generators };
}
