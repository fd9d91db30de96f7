/**
 * Colouring of an IIS result (docs/math.md "Colouring"), in linear light. The GLSL twin lives in
 * glsl/colour (shader issue) and follows these functions line by line.
 */

import type { Coloring, TileSpec } from '../nodes/core/scene.ts';
import type { Circle, Color } from '../nodes/core/values.ts';
import { finiteValue } from '../nodes/formula/checked.ts';
import { COLOUR_NAMES } from '../nodes/formula/names.ts';
import { type PictureMap, resolvePicture, samplePicture } from './picture.ts';
import { placeUv, rotationPair } from './placement.ts';
import { seedColour } from './seeds.ts';
import { type Rgb, toLinear } from './srgb.ts';

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

/** The sRGB colour of an escaped point that needed `depth` steps (modes coloured by depth). */
export function depthColour(coloring: DepthColoring, depth: number): Rgb {
  switch (coloring.mode) {
    case 'depth-hsv':
      return hsvToRgb(coloring.hueOffset + coloring.hueStep * depth, coloring.saturation, coloring.value);
    case 'cosine':
      return cosinePalette(coloring.a, coloring.b, coloring.c, coloring.d, depth * coloring.step);
    case 'parity':
      return [...(depth % 2 === 0 ? coloring.even : coloring.odd)] as Rgb;
  }
}

/** A colouring by a measure of the run (docs/math.md "Colouring by a measure"). */
export type MeasureColoring = Extract<Coloring, { mode: 'measure' }>;

/** What a measure can be read from: the run's final point, its scale, edge distance and trap. */
export interface MeasureSource {
  readonly x: number;
  readonly y: number;
  /** The accumulated scale s (docs/math.md "Length scale"). */
  readonly s: number;
  /** Distance from the final point to the nearest element boundary, in the tile's coordinates. */
  readonly edge: number;
  /** The orbit's least distance to the trap circle (orbitTrapDistance at every point of the path). */
  readonly trap: number;
  /** The depth (inversions applied): read by the `formula` measure. */
  readonly depth: number;
}

/** Distance from (x, y) to the trap circle: ||p − c| − r| (r = 0: a point trap). */
export function orbitTrapDistance(trap: Circle, x: number, y: number): number {
  return Math.abs(Math.hypot(x - trap.c[0], y - trap.c[1]) - trap.r);
}

/**
 * The measure m: x, y, |p|, arg p / 2π (turns, in (−½, ½]), the edge distance, ln s (the escape
 * speed: how much the path magnified, a continuous companion of depth) or the trap distance.
 */
export function measureValue(coloring: MeasureColoring, m: MeasureSource): number {
  switch (coloring.measure) {
    case 'x':
      return m.x;
    case 'y':
      return m.y;
    case 'radius':
      return Math.hypot(m.x, m.y);
    case 'argument':
      return Math.atan2(m.y, m.x) / (2 * Math.PI);
    case 'edge':
      return m.edge;
    case 'speed':
      return Math.log(m.s);
    case 'trap':
      return m.trap;
    case 'formula':
      return colourFormulaValue(coloring.formula ?? '0', m);
  }
}

/** One scratch environment for colour formulas (the CPU renderer is single-threaded per worker). */
const colourEnv = { z: [0, 0] as [number, number], x: 0, y: 0, n: 0, s: 1 };

/**
 * The `formula` measure: the tile's colour function of z = (x, y), n and s (docs/formula.md
 * "Colour functions"); 0 where it is not a finite number, as on the GPU's float path it would be
 * undefined (the tile node refuses a formula that does not check).
 */
export function colourFormulaValue(text: string, m: MeasureSource): number {
  colourEnv.z[0] = m.x;
  colourEnv.z[1] = m.y;
  colourEnv.x = m.x;
  colourEnv.y = m.y;
  colourEnv.n = m.depth;
  colourEnv.s = m.s;
  return finiteValue(text, COLOUR_NAMES, colourEnv);
}

/** Linear colour of a measure m: the cosine palette of t = offset + scale·m. */
export function measureColour(coloring: MeasureColoring, m: number): Rgb {
  const { a, b, c, d, scale, offset } = coloring;
  return toLinear(cosinePalette(a, b, c, d, offset + scale * m));
}

/** The colouring modes whose colour depends on the depth alone. */
export type DepthColoring = Extract<Coloring, { mode: 'depth-hsv' | 'cosine' | 'parity' }>;

/**
 * Linear colour of an escaped point from its final point (x, y) and depth: the picture's texel
 * (image mode: a picture `size` high and size·width/height wide), else depthColour.
 */
export function finalColour(
  coloring: Exclude<Coloring, { mode: 'limit-set' | 'measure' }>,
  depth: number,
  x: number,
  y: number,
  pictures: PictureMap | undefined,
): Rgb {
  if (coloring.mode !== 'image') return toLinear(depthColour(coloring, depth));
  const { image, center, size, rotation } = coloring;
  const [cos, sin] = rotationPair(rotation);
  const [u, v] = placeUv(center[0], center[1], (size * image.width) / image.height, size, cos, sin, x, y);
  return samplePicture(resolvePicture(image.src, pictures), u, v);
}

/** a + (b − a)·t per channel. */
const mixRgb = (a: Rgb, b: Rgb, t: number): Rgb => [
  a[0] + (b[0] - a[0]) * t,
  a[1] + (b[1] - a[1]) * t,
  a[2] + (b[2] - a[2]) * t,
];

export interface ShadeInput {
  readonly escaped: boolean;
  readonly depth: number;
  /** Outside the clip disk: background. */
  readonly clipped: boolean;
  /** Distance to the nearest tile edge in pixels (Infinity when edges are off). */
  readonly edgePixels: number;
  /** The final point (where the run stopped: in the tile, at a seed, or at maxIterations). */
  readonly x: number;
  readonly y: number;
  /**
   * Estimated distance to the limit set in pixels, (edge distance + reach) / s / pixelWorld
   * (far-disk.ts limitReach; Infinity when not estimated).
   */
  readonly limitPixels: number;
  /** Index of the seed the run stopped at, −1 for none. */
  readonly seed: number;
  /** measureValue of the run (measure mode only). */
  readonly measure?: number;
}

/**
 * Linear colour of one sample, decided in this order: clipped → background; a seed → its colour
 * (times max(0, 1 − seedFade·depth));
 * `seedsOnly` → background; limit-set mode → limit colour where not escaped, else the
 * background blended towards it by max(clamp(1 − L, 0, 1), exp(−L/glow)) (L = limitPixels);
 * not escaped → limit colour; outside the `inner` circle → background; depth 0 with a `fill` →
 * the fill; else the mode's colour (measure mode: the palette of r.measure). Edges are drawn with a 1-pixel antialiased falloff.
 */
export function shade(tile: TileSpec, r: ShadeInput, pictures?: PictureMap): Rgb {
  if (r.clipped) return toLinear(tile.background);
  if (r.seed >= 0 && tile.seeds) {
    const c = seedColour(tile.seeds[r.seed], r.x, r.y, pictures);
    if (!tile.seedFade) return c;
    const k = Math.max(0, 1 - tile.seedFade * r.depth);
    return [c[0] * k, c[1] * k, c[2] * k];
  }
  if (tile.seedsOnly) return toLinear(tile.background);
  const coloring = tile.coloring;
  if (coloring.mode === 'limit-set') {
    if (!r.escaped) return toLinear(tile.limitColor);
    // A line about one pixel wide where the estimate falls below a pixel, plus the glow.
    const line = clamp01(1 - r.limitPixels);
    const glow = coloring.glow > 0 ? Math.exp(-r.limitPixels / coloring.glow) : 0;
    return mixRgb(toLinear(tile.background), toLinear(tile.limitColor), Math.max(line, glow));
  }
  if (!r.escaped) return toLinear(tile.limitColor);
  const inner = tile.inner;
  if (inner && (r.x - inner.c[0]) ** 2 + (r.y - inner.c[1]) ** 2 >= inner.r * inner.r)
    return toLinear(tile.background);
  const base =
    r.depth === 0 && tile.fill
      ? toLinear(tile.fill)
      : coloring.mode === 'measure'
        ? measureColour(coloring, r.measure ?? 0)
        : finalColour(coloring, r.depth, r.x, r.y, pictures);
  if (tile.edgeWidth <= 0) return base;
  const t = clamp01(r.edgePixels - tile.edgeWidth / 2 + 0.5);
  const edge = toLinear(tile.edgeColor);
  return [
    edge[0] + (base[0] - edge[0]) * t,
    edge[1] + (base[1] - edge[1]) * t,
    edge[2] + (base[2] - edge[2]) * t,
  ];
}
