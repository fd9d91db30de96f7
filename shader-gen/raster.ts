/**
 * Renders a whole image on the CPU: per pixel, `samples` jittered IIS runs, shaded in linear
 * light, averaged, encoded as 8-bit sRGB RGBA with the first row at the top (PNG order).
 */
import type { Scene } from '../nodes/core/scene.ts';
import { linearToSrgb, type Rgb, shade } from './colour.ts';
import type { IisState } from './elements/element-kind.ts';
import { type PreparedElements, prepare, runIis } from './interpret.ts';
import { pixelToWorld, sampleOffset } from './view.ts';

export interface RasterOptions {
  readonly width: number;
  readonly height: number;
  /** Samples per pixel (default: the scene's). */
  readonly samples?: number;
  /** Called after each row with the fraction done; return false to cancel. */
  readonly onProgress?: (done: number) => boolean | undefined;
}

export interface Raster {
  readonly width: number;
  readonly height: number;
  /** RGBA, 8-bit sRGB, row 0 at the top. */
  readonly data: Uint8ClampedArray;
}

/**
 * Linear colour of one sample at world point (x, y): clip test, IIS run, distance to the nearest
 * tile edge in pixels (d / s / pixelWorld, pixelWorld = world units per pixel), shade. `st` is
 * scratch state (left holding the run's result). The shader's shadeSample is its GLSL twin.
 */
export function sampleColour(
  scene: Scene,
  prepared: PreparedElements,
  x: number,
  y: number,
  pixelWorld: number,
  st: IisState,
): Rgb {
  const { tile, clip } = scene;
  const clipped = clip !== null && (x - clip.c[0]) ** 2 + (y - clip.c[1]) ** 2 > clip.r * clip.r;
  st.x = x;
  st.y = y;
  st.s = 1;
  st.depth = 0;
  const escaped = clipped ? false : runIis(prepared, scene.maxIterations, st);
  let edgePixels = Number.POSITIVE_INFINITY;
  if (tile.edgeWidth > 0 && escaped) {
    let d = Number.POSITIVE_INFINITY;
    for (let i = 0; i < prepared.elements.length; i++) {
      d = Math.min(d, prepared.kinds[i].boundaryDistance(prepared.elements[i], st.x, st.y));
    }
    edgePixels = d / st.s / pixelWorld;
  }
  return shade(tile, { escaped, depth: st.depth, clipped, edgePixels });
}

export function rasterize(scene: Scene, options: RasterOptions): Raster {
  const { width, height } = options;
  const samples = Math.max(1, Math.round(options.samples ?? scene.samples));
  const data = new Uint8ClampedArray(width * height * 4);
  const prepared = prepare(scene.elements);
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
        const c = sampleColour(scene, prepared, x, y, pixelWorld, st);
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
