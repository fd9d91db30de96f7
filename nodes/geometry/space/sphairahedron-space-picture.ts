/**
 * The parameter-space view's pixels (paper Fig. 30), shared by the app's view and the CLI's PNG:
 * each class in its colour, a pixel whose right or lower neighbour has another class drawn as
 * boundary, the zb and zc axes with ticks, and the current parameter as a red point
 * (docs/math-3d.md "The parameter-space view"). Text (tick labels, legend) is the app's.
 */
import { type View, worldToPixel } from '../../core/view.ts';
import type { SpaceClass } from './sphairahedron-space.ts';
import { SPACE_CLASSES } from './sphairahedron-space.ts';
import { hasZc, paintSpace, UNPAINTED } from './sphairahedron-space-paint.ts';

export const SPACE_COLOURS: Readonly<Record<SpaceClass, string>> = {
  valid: '#5fb86a',
  bridge: '#4a90d9',
  tunnel: '#e3963e',
  'bridge-tunnel': '#a465c8',
  degenerate: '#2b2b30',
};

export const SPACE_NAMES: Readonly<Record<SpaceClass, string>> = {
  valid: 'valid (a sphairahedron of the type)',
  bridge: 'bridges',
  tunnel: 'tunnels',
  'bridge-tunnel': 'bridges and tunnels',
  degenerate: 'no shape (a radius ≤ 0)',
};

const rgb = (hex: string): [number, number, number] => [
  Number.parseInt(hex.slice(1, 3), 16),
  Number.parseInt(hex.slice(3, 5), 16),
  Number.parseInt(hex.slice(5, 7), 16),
];
const CLASS_RGB = SPACE_CLASSES.map((c) => rgb(SPACE_COLOURS[c]));
const BOUNDARY: [number, number, number] = [244, 244, 244];
const UNPAINTED_RGB: [number, number, number] = [20, 20, 24];
const AXIS: [number, number, number] = [16, 16, 16];
const POINT: [number, number, number] = [229, 57, 53];

/**
 * Tick values of a range: multiples of 1, 2 or 5 × 10^k, the step the first of these that gives at
 * most `most` ticks.
 */
export function spaceTicks(lo: number, hi: number, most = 8): number[] {
  const span = hi - lo;
  if (!(span > 0) || !Number.isFinite(span)) return [];
  const base = 10 ** Math.floor(Math.log10(span / most));
  const step = [1, 2, 5, 10].map((m) => m * base).find((s) => span / s <= most) ?? 10 * base;
  const out: number[] = [];
  for (let k = Math.ceil(lo / step); k * step <= hi; k++) out.push(Math.round(k * step * 1e9) / 1e9);
  return out;
}

/** The window of a width × height picture of `view`: its zb and zc ranges. */
export function spaceWindow(view: View, width: number, height: number) {
  const half = view.scale / 2;
  const wide = (half * width) / height;
  return {
    zb: [view.center[0] - wide, view.center[0] + wide] as const,
    zc: [view.center[1] - half, view.center[1] + half] as const,
  };
}

/** Screen position (x right, y down, pixel corners) of the parameter (zb, zc). */
export function spaceScreen(
  view: View,
  width: number,
  height: number,
  zb: number,
  zc: number,
): [number, number] {
  const [x, y] = worldToPixel(view, width, height, [zb, zc]);
  return [x, height - y];
}

/**
 * The picture's RGBA pixels (row 0 at the top): classes, boundaries, axes with ticks and, when
 * given, the parameter as a red point ringed in white. `zcAxis` false: a zb-only type (no zc axis).
 */
export function spaceRgba(
  classes: Uint8Array,
  width: number,
  height: number,
  view: View,
  options: { readonly point?: readonly [number, number]; readonly zcAxis: boolean },
  out = new Uint8ClampedArray(width * height * 4),
): Uint8ClampedArray {
  const put = (x: number, y: number, c: readonly number[]) => {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const o = (y * width + x) * 4;
    out[o] = c[0]!;
    out[o + 1] = c[1]!;
    out[o + 2] = c[2]!;
    out[o + 3] = 255;
  };
  for (let y = 0; y < height; y++)
    for (let x = 0; x < width; x++) {
      const k = classes[y * width + x]!;
      const right = x + 1 < width ? classes[y * width + x + 1]! : k;
      const below = y + 1 < height ? classes[(y + 1) * width + x]! : k;
      const edge =
        k !== UNPAINTED && ((right !== k && right !== UNPAINTED) || (below !== k && below !== UNPAINTED));
      put(x, y, edge ? BOUNDARY : k === UNPAINTED ? UNPAINTED_RGB : CLASS_RGB[k]!);
    }
  // The axes: zb = 0 (vertical) and zc = 0 (horizontal), ticks across them.
  const [x0, y0] = spaceScreen(view, width, height, 0, 0).map(Math.floor) as [number, number];
  const win = spaceWindow(view, width, height);
  if (options.zcAxis) for (let y = 0; y < height; y++) put(x0, y, AXIS);
  for (let x = 0; x < width; x++) put(x, y0, AXIS);
  for (const t of spaceTicks(win.zb[0], win.zb[1])) {
    const x = Math.floor(spaceScreen(view, width, height, t, 0)[0]);
    for (let d = -4; d <= 4; d++) put(x, y0 + d, AXIS);
  }
  if (options.zcAxis)
    for (const t of spaceTicks(win.zc[0], win.zc[1])) {
      const y = Math.floor(spaceScreen(view, width, height, 0, t)[1]);
      for (let d = -4; d <= 4; d++) put(x0 + d, y, AXIS);
    }
  if (options.point) {
    const [px, py] = spaceScreen(view, width, height, options.point[0], options.point[1]);
    for (let dy = -7; dy <= 7; dy++)
      for (let dx = -7; dx <= 7; dx++) {
        const r = Math.hypot(dx + 0.5, dy + 0.5);
        if (r <= 7) put(Math.floor(px + dx), Math.floor(py + dy), r <= 5.5 ? POINT : BOUNDARY);
      }
  }
  return out;
}

/** An RGBA picture, row 0 at the top (the CPU renderers' output). */
interface Rgba {
  readonly width: number;
  readonly height: number;
  readonly data: Uint8Array | Uint8ClampedArray;
}

/**
 * The parameter-space view as the small panel in a picture's lower right corner (paper Fig. 30:
 * the quasi-sphere with its parameter as a red point in the panel), for the CLI's PNG: a square
 * of 0.4 of the picture's shorter side, zb, zc ∈ [−2.5, 2.5], framed in white.
 */
export function insetSpaceView(
  image: Rgba,
  target: { readonly type: Parameters<typeof hasZc>[0]; readonly zb: number; readonly zc: number },
): void {
  const side = Math.max(8, Math.round(Math.min(image.width, image.height) * 0.4));
  const frame = 2;
  const view: View = { center: [0, 0], scale: 5 };
  const zcAxis = hasZc(target.type);
  const classes = paintSpace(target.type, view, side, side);
  const point = [target.zb, zcAxis ? target.zc : 0] as const;
  const panel = spaceRgba(classes, side, side, view, { point, zcAxis });
  const left = image.width - side - frame - 4;
  const top = image.height - side - frame - 4;
  for (let y = -frame; y < side + frame; y++)
    for (let x = -frame; x < side + frame; x++) {
      const o = ((top + y) * image.width + left + x) * 4;
      const inside = x >= 0 && y >= 0 && x < side && y < side;
      const i = (y * side + x) * 4;
      for (let k = 0; k < 4; k++) image.data[o + k] = inside ? panel[i + k]! : 255;
    }
}
