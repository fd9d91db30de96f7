/**
 * The SVG text of a vector picture (enumerate.ts): pure string building, no DOM. The world maps to
 * the image as the raster does (view.ts: the view height fills the image height), y pointing up;
 * curves outside the view or the clip disk are left out, the rest is clipped to the clip disk.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import type { Circle, Color } from '../../nodes/core/values.ts';
import { depthColour } from '../colour.ts';
import type { FigureLayer } from '../figures/layer.ts';
import type { Curve } from './curves.ts';
import type { VectorCurve, VectorSeed } from './enumerate.ts';

export interface SvgResult {
  readonly svg: string;
  /** <circle>/<line> elements written for edges and seeds (the background and clip not counted). */
  readonly edgeCount: number;
  readonly seedCount: number;
  /** Strokes and dots written for the render node's figures (Cayley graph, depth-first limit set). */
  readonly figureCount: number;
}

/** An sRGB colour in [0, 1]³ as #rrggbb. */
export function hexColour(c: Color): string {
  const byte = (v: number) =>
    Math.round(Math.min(1, Math.max(0, v)) * 255)
      .toString(16)
      .padStart(2, '0');
  return `#${byte(c[0])}${byte(c[1])}${byte(c[2])}`;
}

const num = (v: number): string => String(Math.round(v * 1000) / 1000);

interface Frame {
  readonly width: number;
  readonly height: number;
  /** Pixels per world unit. */
  readonly k: number;
  readonly cx: number;
  readonly cy: number;
}

const toX = (f: Frame, x: number) => (x - f.cx) * f.k + f.width / 2;
const toY = (f: Frame, y: number) => f.height / 2 - (y - f.cy) * f.k;

/** Whether the curve's stroke can show in the image and inside the clip disk (in image pixels). */
function visible(f: Frame, k: Curve, clip: Circle | null): boolean {
  if (k.kind === 'line') {
    // Distance from the image centre to the line against half the image diagonal.
    const d = Math.abs((f.cx - k.q[0]) * k.n[0] + (f.cy - k.q[1]) * k.n[1]) * f.k;
    return d <= Math.hypot(f.width, f.height) / 2 + 1;
  }
  const x = toX(f, k.c[0]);
  const y = toY(f, k.c[1]);
  const r = k.r * f.k;
  // Nearest and farthest image points from the centre: the circle misses the image when the image
  // lies wholly inside it or wholly outside it.
  const nx = Math.min(Math.max(x, 0), f.width) - x;
  const ny = Math.min(Math.max(y, 0), f.height) - y;
  const fx = Math.max(x, f.width - x);
  const fy = Math.max(y, f.height - y);
  if (Math.hypot(nx, ny) > r + 1 || Math.hypot(fx, fy) < r - 1) return false;
  if (!clip) return true;
  const dc = Math.hypot(k.c[0] - clip.c[0], k.c[1] - clip.c[1]);
  return dc < k.r + clip.r && dc + clip.r > k.r && dc + k.r > clip.r - 1 / f.k;
}

function curveElement(f: Frame, k: Curve, attrs: string): string {
  if (k.kind === 'circle') {
    return `<circle cx="${num(toX(f, k.c[0]))}" cy="${num(toY(f, k.c[1]))}" r="${num(k.r * f.k)}"${attrs}/>`;
  }
  // A segment through the foot of the image centre, long enough to cross the whole image.
  const h = (f.cx - k.q[0]) * k.n[0] + (f.cy - k.q[1]) * k.n[1];
  const px = f.cx - h * k.n[0];
  const py = f.cy - h * k.n[1];
  const len = Math.hypot(f.width, f.height) / f.k;
  const tx = -k.n[1] * len;
  const ty = k.n[0] * len;
  return `<line x1="${num(toX(f, px - tx))}" y1="${num(toY(f, py - ty))}" x2="${num(toX(f, px + tx))}" y2="${num(toY(f, py + ty))}"${attrs}/>`;
}

/** Stroke colour of an edge of depth n: the edge colour when edges are drawn, else the depth's colour. */
function edgeStroke(scene: Scene, depth: number): Color {
  const { tile } = scene;
  if (tile.edgeWidth > 0) return tile.edgeColor;
  const c = tile.coloring;
  if (c.mode === 'depth-hsv' || c.mode === 'cosine' || c.mode === 'parity') return depthColour(c, depth + 1);
  return tile.limitColor;
}

/** Fill inside the clip disk: the fundamental tile's colour where the scene has one. */
function insideFill(scene: Scene): Color {
  const { tile } = scene;
  if (tile.fill) return tile.fill;
  const c = tile.coloring;
  if (c.mode === 'depth-hsv' || c.mode === 'cosine' || c.mode === 'parity') return depthColour(c, 0);
  return tile.background;
}

export function writeSvg(
  scene: Scene,
  picture: { readonly edges: readonly VectorCurve[]; readonly seeds: readonly VectorSeed[] },
  width: number,
  height: number,
  figures?: FigureLayer,
): SvgResult {
  const { view, clip, tile } = scene;
  const f: Frame = { width, height, k: height / view.scale, cx: view.center[0], cy: view.center[1] };
  const strokeWidth = num(tile.edgeWidth > 0 ? tile.edgeWidth : 1);
  const lines: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}">`,
    `<rect width="${width}" height="${height}" fill="${hexColour(clip ? tile.background : insideFill(scene))}"/>`,
  ];
  let body = '<g>';
  if (clip) {
    const disk = curveElement(f, { kind: 'circle', c: clip.c, r: clip.r }, '');
    lines.push(`<defs><clipPath id="clip">${disk}</clipPath></defs>`);
    lines.push(
      curveElement(f, { kind: 'circle', c: clip.c, r: clip.r }, ` fill="${hexColour(insideFill(scene))}"`),
    );
    body = '<g clip-path="url(#clip)">';
  }
  lines.push(body);
  let seedCount = 0;
  for (const s of picture.seeds) {
    if (!visible(f, s.curve, clip) && !(s.curve.kind === 'circle' && s.curve.r * f.k > width + height))
      continue;
    lines.push(curveElement(f, s.curve, ` fill="${hexColour(s.color)}"`));
    seedCount++;
  }
  lines.push(`<g fill="none" stroke-width="${strokeWidth}">`);
  let edgeCount = 0;
  for (const e of picture.edges) {
    if (!visible(f, e.curve, clip)) continue;
    lines.push(curveElement(f, e.curve, ` stroke="${hexColour(edgeStroke(scene, e.depth))}"`));
    edgeCount++;
  }
  lines.push('</g>', '</g>');
  const figureCount =
    figures && figures.strokes.length + figures.dots.length > 0 ? writeFigures(f, figures, lines) : 0;
  lines.push('</svg>', '');
  return { svg: lines.join('\n'), edgeCount, seedCount, figureCount };
}

/** The figures over the picture (not clipped: a Cayley graph's geodesics stay in the disk). */
function writeFigures(f: Frame, layer: FigureLayer, lines: string[]): number {
  const pt = (p: readonly [number, number]) => `${num(toX(f, p[0]))},${num(toY(f, p[1]))}`;
  lines.push('<g class="figures" fill="none" stroke-linecap="round" stroke-linejoin="round">');
  for (const s of layer.strokes) {
    lines.push(
      `<polyline points="${s.points.map(pt).join(' ')}" stroke="${hexColour(s.color)}" stroke-width="${num(s.width)}"/>`,
    );
  }
  for (const d of layer.dots) {
    lines.push(
      `<circle cx="${num(toX(f, d.at[0]))}" cy="${num(toY(f, d.at[1]))}" r="${num(d.r)}" fill="${hexColour(d.color)}"/>`,
    );
  }
  for (const l of layer.labels) {
    lines.push(
      `<text x="${num(toX(f, l.at[0]) + 4)}" y="${num(toY(f, l.at[1]) - 4)}" fill="${hexColour(l.color)}" font-family="sans-serif" font-size="14" font-weight="bold">${l.text}</text>`,
    );
  }
  lines.push('</g>');
  return layer.strokes.length + layer.dots.length;
}
