/**
 * Renders a Scene3d on the CPU (the reference for the GPU, and `kleinflow render` for 3D graphs):
 * per pixel `samples` jittered rays (the 2D sample pattern, shader-gen/view.ts), shaded in linear
 * light, averaged, encoded as 8-bit sRGB RGBA with row 0 at the TOP (PNG order). A probe image
 * gives what parity compares: (hit, t, depth, seed) per pixel, row 0 at the BOTTOM like the GPU.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { linearToSrgb, toLinear } from '../srgb.ts';
import { sampleOffset } from '../view.ts';
import { cameraBasis, pixelAngle, rayDirection } from './camera-3d.ts';
import { prepareTrace3d, type TracePlan } from './plan.ts';
import { shadeHit } from './shade-3d.ts';
import { type Hit3d, traceRay } from './trace-3d.ts';

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
export function tracePixel(plan: TracePlan, width: number, height: number, px: number, py: number) {
  const basis = cameraBasis(plan.scene.camera);
  const d = rayDirection(basis, width, height, px, py);
  const angle = pixelAngle(basis, height);
  return { o: basis.origin, d, angle, hit: traceRay(plan, basis.origin, d, angle) };
}

export function renderScene3d(
  scene: Scene3d,
  width: number,
  height: number,
  options: Render3dOptions = {},
): Raster3d {
  const plan = prepareTrace3d(scene);
  const samples = Math.max(1, Math.round(options.samples ?? scene.samples));
  const bg = toLinear(scene.background);
  const bgAlpha = options.bgAlpha ?? 1;
  const data = new Uint8ClampedArray(width * height * 4);
  for (let row = 0; row < height; row++) {
    const py = height - 1 - row;
    for (let px = 0; px < width; px++) {
      const sum = [0, 0, 0, 0];
      for (let k = 0; k < samples; k++) {
        const [jx, jy] = sampleOffset(k);
        const { o, d, angle, hit } = tracePixel(plan, width, height, px + jx, py + jy);
        const c = hit.hit ? shadeHit(plan, o, d, angle, hit) : bg;
        const a = hit.hit ? 1 : bgAlpha;
        for (let i = 0; i < 3; i++) sum[i]! += c[i]! * a;
        sum[3]! += a;
      }
      const o = 4 * (row * width + px);
      const alpha = sum[3]! / samples;
      for (let i = 0; i < 3; i++)
        data[o + i] = Math.round(255 * linearToSrgb(Math.min(1, alpha > 0 ? sum[i]! / sum[3]! : 0)));
      data[o + 3] = Math.round(255 * alpha);
    }
    if (options.onProgress?.((row + 1) / height) === false) break;
  }
  return { width, height, data };
}

/** (hit 0/1, t, depth, seed) per pixel centre, row 0 at the bottom — what GPU parity compares. */
export function probeScene3d(
  scene: Scene3d,
  width: number,
  height: number,
  jitter: readonly [number, number] = [0.5, 0.5],
): Float32Array {
  const plan = prepareTrace3d(scene);
  const out = new Float32Array(width * height * 4);
  for (let py = 0; py < height; py++) {
    for (let px = 0; px < width; px++) {
      const h: Hit3d = tracePixel(plan, width, height, px + jitter[0], py + jitter[1]).hit;
      out.set([h.hit ? 1 : 0, h.t, h.depth, h.seed], 4 * (py * width + px));
    }
  }
  return out;
}
