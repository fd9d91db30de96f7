/**
 * Renders a Scene3d on the CPU (the reference for the GPU, and `kleinflow render` for 3D graphs):
 * per pixel `samples` jittered rays (the 2D sample pattern, shader-gen/view.ts), shaded in linear
 * light (mirror seeds reflecting, reflect-3d.ts), averaged, encoded as 8-bit sRGB RGBA with row 0 at the TOP (PNG order). A probe image
 * gives what parity compares: (hit, t, depth, seed) per pixel, row 0 at the BOTTOM like the GPU.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { linearToSrgb, toLinear } from '../srgb.ts';
import { sampleOffset } from '../view.ts';
import { type CameraBasis, cameraBasis, pixelAngle, rayDirection } from './camera-3d.ts';
import { prepareTrace3d, type TracePlan } from './plan.ts';
import { type Environment, environmentOf, radiance } from './reflect-3d.ts';
import { type Hit3d, traceRay } from './trace-3d.ts';
import { overBackground, type VolumeBounds, volumeBounds, volumeJitter, volumeRay } from './volume-3d.ts';

export interface Render3dOptions {
  /** Samples per pixel (default: the scene's). */
  readonly samples?: number;
  /** Called after each row with the fraction done; return false to cancel. */
  readonly onProgress?: (done: number) => boolean | undefined;
  /** Alpha of background pixels (1; 0 for a transparent PNG). */
  readonly bgAlpha?: number;
}

export interface Raster3d {
  readonly width: number;
  readonly height: number;
  /** RGBA, 8-bit sRGB, row 0 at the top. */
  readonly data: Uint8ClampedArray;
}

/** Traces the ray through image point (px, py) (py from the bottom) of a width × height image. */
export function tracePixel(
  plan: TracePlan,
  width: number,
  height: number,
  px: number,
  py: number,
  basis: CameraBasis = cameraBasis(plan.scene.camera),
) {
  const d = rayDirection(basis, width, height, px, py);
  const angle = pixelAngle(basis, height);
  return { o: basis.origin, d, angle, hit: traceRay(plan, basis.origin, d, angle) };
}

/**
 * What every pixel of one render shares, built once per thread: the trace plan and the settings.
 * A pixel's colour depends on nothing else (no state carries from pixel to pixel, the sample
 * jitter is a function of the sample index), so any set of rows rendered anywhere, in any order,
 * gives the bytes of the whole render: `kleinflow render` splits an image into bands this way.
 */
export interface Render3dFrame {
  readonly plan: TracePlan;
  readonly basis: CameraBasis;
  readonly width: number;
  readonly height: number;
  readonly samples: number;
  /** What rays that hit nothing see (the background; also what mirrors reflect). */
  readonly env: Environment;
  /** The flat background colour (linear), under the volume renderer's medium. */
  readonly bg: readonly number[];
  readonly bgAlpha: number;
  /** The volume renderer's bounds (volume-3d.ts), when the scene is volume rendered. */
  readonly volumeBounds: VolumeBounds | null;
}

export function render3dFrame(
  scene: Scene3d,
  width: number,
  height: number,
  options: Omit<Render3dOptions, 'onProgress'> = {},
): Render3dFrame {
  const plan = prepareTrace3d(scene);
  return {
    plan,
    volumeBounds: scene.volume ? volumeBounds(plan) : null,
    basis: cameraBasis(scene.camera),
    width,
    height,
    samples: Math.max(1, Math.round(options.samples ?? scene.samples)),
    env: environmentOf(scene),
    bg: toLinear(scene.background),
    bgAlpha: options.bgAlpha ?? 1,
  };
}

/** Pixel (px, row), row 0 at the TOP, as RGBA bytes written to data[o … o + 3]. */
export function renderPixel3d(f: Render3dFrame, px: number, row: number, data: Uint8ClampedArray, o: number) {
  const py = f.height - 1 - row;
  const sum = [0, 0, 0, 0];
  const volume = f.plan.scene.volume;
  for (let k = 0; k < f.samples; k++) {
    const [jx, jy] = sampleOffset(k);
    let c: readonly number[];
    let a: number;
    if (volume) {
      const d = rayDirection(f.basis, f.width, f.height, px + jx, py + jy);
      const ray = volumeRay(f.plan, f.volumeBounds, volume, f.basis.origin, d, volumeJitter(px, py));
      [c, a] = overBackground(ray, f.bg, f.bgAlpha);
    } else {
      const { o: origin, d, angle, hit } = tracePixel(f.plan, f.width, f.height, px + jx, py + jy, f.basis);
      c = radiance(f.plan, f.env, origin, d, angle, hit);
      a = hit.hit ? 1 : f.bgAlpha;
    }
    for (let i = 0; i < 3; i++) sum[i]! += c[i]! * a;
    sum[3]! += a;
  }
  const alpha = sum[3]! / f.samples;
  for (let i = 0; i < 3; i++)
    data[o + i] = Math.round(255 * linearToSrgb(Math.min(1, alpha > 0 ? sum[i]! / sum[3]! : 0)));
  data[o + 3] = Math.round(255 * alpha);
}

/**
 * Rows start … end − 1 (row 0 at the top) into `data`, row `start` at offset 0. `onRow` gets the
 * number of rows done and may return false to stop; returns whether every row was rendered.
 */
export function renderRows3d(
  f: Render3dFrame,
  start: number,
  end: number,
  data: Uint8ClampedArray,
  onRow?: (rowsDone: number) => boolean | undefined,
): boolean {
  for (let row = start; row < end; row++) {
    const base = 4 * (row - start) * f.width;
    for (let px = 0; px < f.width; px++) renderPixel3d(f, px, row, data, base + 4 * px);
    if (onRow?.(row + 1 - start) === false) return false;
  }
  return true;
}

export function renderScene3d(
  scene: Scene3d,
  width: number,
  height: number,
  options: Render3dOptions = {},
): Raster3d {
  const data = new Uint8ClampedArray(width * height * 4);
  renderRows3d(render3dFrame(scene, width, height, options), 0, height, data, (rows) =>
    options.onProgress?.(rows / height),
  );
  return { width, height, data };
}

/**
 * The volume probe per pixel centre, row 0 at the bottom: (opacity 1 − T, optical depth τ, samples
 * taken, 0) — what GPU parity compares for a volume-rendered scene (compile3d's 'volume-probe').
 */
export function probeVolume3d(scene: Scene3d, width: number, height: number): Float32Array {
  const f = render3dFrame(scene, width, height);
  const volume = scene.volume;
  if (!volume) throw new Error('probeVolume3d needs a volume-rendered scene');
  const out = new Float32Array(width * height * 4);
  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      const d = rayDirection(f.basis, width, height, px + 0.5, py + 0.5);
      const r = volumeRay(f.plan, f.volumeBounds, volume, f.basis.origin, d, volumeJitter(px, py));
      out.set([1 - r.transmittance, r.opticalDepth, r.samples, 0], 4 * (py * width + px));
    }
  }
  return out;
}

/** (hit 0/1, t, depth, seed) per pixel centre, row 0 at the bottom — what GPU parity compares. */
export function probeScene3d(
  scene: Scene3d,
  width: number,
  height: number,
  jitter: readonly [number, number] = [0.5, 0.5],
): Float32Array {
  const plan = prepareTrace3d(scene);
  const basis = cameraBasis(scene.camera);
  const out = new Float32Array(width * height * 4);
  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      const h: Hit3d = tracePixel(plan, width, height, px + jitter[0], py + jitter[1], basis).hit;
      out.set([h.hit ? 1 : 0, h.t, h.depth, h.seed], 4 * (py * width + px));
    }
  }
  return out;
}
