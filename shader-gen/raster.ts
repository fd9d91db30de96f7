/**
 * Renders a whole image on the CPU: per pixel, `samples` jittered IIS runs, shaded in linear
 * light, averaged, encoded as 8-bit sRGB RGBA with the first row at the top (PNG order).
 */
import type { Scene } from '../nodes/core/scene.ts';
import type { Circle } from '../nodes/core/values.ts';
import { pixelToWorld } from '../nodes/core/view.ts';
import { measureValue, orbitTrapDistance, shade } from './colour.ts';
import type { IisState } from './elements/element-kind.ts';
import { farDisk, farDistance, limitReach } from './far-disk.ts';
import { type PreparedElements, prepare, runIis } from './interpret.ts';
import type { PictureMap } from './picture.ts';
import { seedAt } from './seeds.ts';
import { linearToSrgb, type Rgb } from './srgb.ts';
import { outsideClip } from './trace.ts';
import { sampleOffset } from './view.ts';

export interface RasterOptions {
  readonly width: number;
  readonly height: number;
  /** Samples per pixel (default: the scene's). */
  readonly samples?: number;
  /** Called after each row with the fraction done; return false to cancel. */
  readonly onProgress?: (done: number) => boolean | undefined;
  /** Decoded pixels of the pictures the scene uses, by src (the built-in one needs none). */
  readonly pictures?: PictureMap;
}

export interface Raster {
  readonly width: number;
  readonly height: number;
  /** RGBA, 8-bit sRGB, row 0 at the top. */
  readonly data: Uint8ClampedArray;
}

/** Per-image data sampleColour reads (prepared once by rasterize; tests prepare it too). */
export interface SampleContext {
  readonly prepared: PreparedElements;
  /** The bounding circle of all insides when ∞ lies in the tile (far-disk.ts), else null. */
  readonly far: Circle | null;
  /** far-disk.ts limitReach (the limit-set colouring's distance estimate). */
  readonly reach: number | null;
  readonly pictures?: PictureMap;
}

export function sampleContext(scene: Scene, pictures?: PictureMap): SampleContext {
  return {
    prepared: prepare(scene.elements),
    far: farDisk(scene.elements),
    reach: limitReach(scene.elements),
    pictures,
  };
}

/**
 * Linear colour of one sample at world point (x, y): clip test, IIS run (stopping at the first
 * seed that holds the point at the start of a step), distance to the nearest tile edge in pixels
 * (max(d, far distance) / s / pixelWorld, pixelWorld = world units per pixel) and, in limit-set
 * mode, to the limit set ((that + reach) / s / pixelWorld), the measure (measure mode; an orbit
 * trap sees every point of the path), shade. `st` is
 * scratch state (left holding the run's result). The shader's shadeSample is its GLSL twin.
 */
export function sampleColour(
  scene: Scene,
  ctx: SampleContext,
  x: number,
  y: number,
  pixelWorld: number,
  st: IisState,
): Rgb {
  const { tile, clip } = scene;
  const { prepared, far } = ctx;
  const clipped = outsideClip(clip, x, y);
  st.x = x;
  st.y = y;
  st.s = 1;
  st.depth = 0;
  const seeds = tile.seeds ?? [];
  const coloring = tile.coloring;
  const trap = coloring.mode === 'measure' && coloring.measure === 'trap' ? coloring.trap : null;
  let seed = -1;
  let trapDistance = Number.POSITIVE_INFINITY;
  // At the start of every pass (interpret.ts runIis's visit): the trap sees the point, then a point
  // in a seed stops the run.
  const visit =
    seeds.length > 0 || trap
      ? (at: IisState) => {
          if (trap) trapDistance = Math.min(trapDistance, orbitTrapDistance(trap, at.x, at.y));
          if (seeds.length === 0) return false;
          seed = seedAt(seeds, at.x, at.y);
          return seed >= 0;
        }
      : undefined;
  const escaped = clipped ? false : runIis(prepared, scene.maxIterations, st, visit);
  const limitSet = coloring.mode === 'limit-set';
  const edgeMeasure = coloring.mode === 'measure' && coloring.measure === 'edge';
  let edgePixels = Number.POSITIVE_INFINITY;
  let limitPixels = Number.POSITIVE_INFINITY;
  let d = Number.POSITIVE_INFINITY;
  if ((tile.edgeWidth > 0 || limitSet || edgeMeasure) && escaped) {
    for (let i = 0; i < prepared.elements.length; i++) {
      d = Math.min(d, prepared.kinds[i].boundaryDistance(prepared.elements[i], st.x, st.y));
    }
    if (far) d = Math.max(d, farDistance(far, st.x, st.y));
    edgePixels = d / st.s / pixelWorld;
    if (limitSet && ctx.reach !== null) limitPixels = (d + ctx.reach) / st.s / pixelWorld;
  }
  const measure =
    coloring.mode === 'measure'
      ? measureValue(coloring, { x: st.x, y: st.y, s: st.s, edge: d, trap: trapDistance, depth: st.depth })
      : undefined;
  return shade(
    tile,
    { escaped, depth: st.depth, clipped, edgePixels, x: st.x, y: st.y, limitPixels, seed, measure },
    ctx.pictures,
  );
}

export function rasterize(scene: Scene, options: RasterOptions): Raster {
  const { width, height } = options;
  const samples = Math.max(1, Math.round(options.samples ?? scene.samples));
  const data = new Uint8ClampedArray(width * height * 4);
  const ctx = sampleContext(scene, options.pictures);
  const { view } = scene;
  const pixelWorld = view.scale / height;
  const offsets = Array.from({ length: samples }, (_, k) => sampleOffset(k));
  const st: IisState = { x: 0, y: 0, s: 1, depth: 0 };
  const acc = [0, 0, 0];

  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      acc[0] = acc[1] = acc[2] = 0;
      for (const [ox, oy] of offsets) {
        const [x, y] = pixelToWorld(view, width, height, px, py, ox, oy);
        const c = sampleColour(scene, ctx, x, y, pixelWorld, st);
        acc[0] += c[0];
        acc[1] += c[1];
        acc[2] += c[2];
      }
      const o = ((height - 1 - py) * width + px) * 4;
      data[o] = Math.round(linearToSrgb(acc[0] / samples) * 255);
      data[o + 1] = Math.round(linearToSrgb(acc[1] / samples) * 255);
      data[o + 2] = Math.round(linearToSrgb(acc[2] / samples) * 255);
      data[o + 3] = 255;
    }
    if (options.onProgress && options.onProgress((py + 1) / height) === false) break;
  }
  return { width, height, data };
}
