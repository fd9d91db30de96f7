/**
 * Colouring of an IIS result (math.md "Colouring"), in linear light. The GLSL twin lives in
 * glsl/colour (shader issue) and follows these functions line by line.
 */
import type { Coloring, TileSpec } from '../nodes/core/scene.ts';
import type { Color } from '../nodes/core/values.ts';

export type Rgb = [number, number, number];

/** sRGB transfer function, decoding: c ≤ 0.04045 ? c/12.92 : ((c+0.055)/1.055)^2.4. */
export const srgbToLinear = (c: number): number => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
/** sRGB transfer function, encoding: c ≤ 0.0031308 ? 12.92c : 1.055 c^(1/2.4) − 0.055. */
export const linearToSrgb = (c: number): number =>
  c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;

export const toLinear = (c: Color): Rgb => [srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])];

const clamp01 = (v: number) => Math.min(1, Math.max(0, v));
const fract = (v: number) => v - Math.floor(v);

/** HSV (all in [0,1], hue in turns) → sRGB: c = v − v s clamp(|fract(h + k/3)·6 − 3| − 1, 0, 1), k = 0, 2, 1 for r, g, b. */
export function hsvToRgb(h: number, s: number, v: number): Rgb {
  const ch = (k: number) => v * (1 - s * (1 - clamp01(Math.abs(fract(h + k / 3) * 6 - 3) - 1)));
  return [ch(0), ch(2), ch(1)];
}

/** Cosine palette a + b cos(2π(c t + d)), clamped to [0, 1] (sRGB). */
export function cosinePalette(a: Color, b: Color, c: Color, d: Color, t: number): Rgb {
  const ch = (i: number) => clamp01(a[i] + b[i] * Math.cos(2 * Math.PI * (c[i] * t + d[i])));
  return [ch(0), ch(1), ch(2)];
}

/** The sRGB colour of an escaped point that needed `depth` steps. */
export function depthColour(coloring: Coloring, depth: number): Rgb {
  switch (coloring.mode) {
    case 'depth-hsv':
      return hsvToRgb(coloring.hueOffset + coloring.hueStep * depth, coloring.saturation, coloring.value);
    case 'cosine':
      return cosinePalette(coloring.a, coloring.b, coloring.c, coloring.d, depth * coloring.step);
    case 'parity':
      return [...(depth % 2 === 0 ? coloring.even : coloring.odd)] as Rgb;
  }
}

export interface ShadeInput {
  readonly escaped: boolean;
  readonly depth: number;
  /** Outside the clip disk: background. */
  readonly clipped: boolean;
  /** Distance to the nearest tile edge in pixels (Infinity when edges are off). */
  readonly edgePixels: number;
}

/** Linear colour of one sample. Edges are drawn with a 1-pixel antialiased falloff. */
export function shade(tile: TileSpec, r: ShadeInput): Rgb {
  if (r.clipped) return toLinear(tile.background);
  if (!r.escaped) return toLinear(tile.limitColor);
  const base = toLinear(depthColour(tile.coloring, r.depth) as unknown as Color);
  if (tile.edgeWidth <= 0) return base;
  const t = clamp01(r.edgePixels - tile.edgeWidth / 2 + 0.5);
  const edge = toLinear(tile.edgeColor);
  return [
    edge[0] + (base[0] - edge[0]) * t,
    edge[1] + (base[1] - edge[1]) * t,
    edge[2] + (base[2] - edge[2]) * t,
  ];
}
