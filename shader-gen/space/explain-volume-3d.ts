/**
 * "Explain this pixel" for a volume-rendered 3D graph (docs/math-3d.md "§11 Volume rendering of the
 * nesting depth"), on the CPU: the ray through the pixel is integrated by the renderer's own
 * volumeRay (volume-3d.ts), watched through its observer, so the samples, the depths seen, the
 * opacity and the early exit are the render's, not a second copy of the loop. The depths along the
 * ray come as runs: consecutive samples of the same depth k, front to back.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import type { Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { linearToSrgb, type Rgb, toLinear } from '../srgb.ts';
import { cameraBasis, rayDirection } from './camera-3d.ts';
import { prepareTrace3d } from './plan.ts';
import { EXIT_TRANSMITTANCE, overBackground, volumeBounds, volumeJitter, volumeRay } from './volume-3d.ts';

/** Consecutive samples along the ray at one nesting depth. */
export interface DepthRun {
  readonly depth: number;
  /** How many samples in a row had this depth. */
  readonly samples: number;
  /** The distance along the ray of the run's first sample. */
  readonly from: number;
}

export interface VolumeTrace3d {
  readonly origin: Vec3;
  readonly direction: Vec3;
  /** Where the ray is inside the volume's bounds [t₀, t₁], or null when it misses them (no samples). */
  readonly span: readonly [number, number] | null;
  /** Δt between samples, and the sample offset j of the pixel (t_i = t₀ + (i + j)·Δt). */
  readonly dt: number;
  readonly jitter: number;
  /** Samples the render asks for (the `volume samples` setting) and the samples it took. */
  readonly steps: number;
  readonly samples: number;
  /** The depths seen along the ray, front to back. */
  readonly runs: readonly DepthRun[];
  /** The greatest depth seen (0 when none). */
  readonly deepest: number;
  /** 1 − T, and the optical depth τ = Σ σ_i Δt. */
  readonly opacity: number;
  readonly opticalDepth: number;
  /** Whether the ray turned opaque (T < EXIT_TRANSMITTANCE) before its last sample. */
  readonly exitedEarly: boolean;
  /** The ray's colour over the background: straight sRGB in [0, 1], and its alpha. */
  readonly colour: Rgb;
  readonly alpha: number;
}

/**
 * The volume ray through image point (px, py) of a width × height picture, py counted from the
 * BOTTOM (as gl_FragCoord), through `scene.camera`; the sample offset is the offset of the pixel
 * holding the point, as the render uses it.
 */
export function explainVolumePixel3d(
  scene: Scene3d,
  width: number,
  height: number,
  px: number,
  py: number,
): VolumeTrace3d {
  const volume = scene.volume;
  if (!volume) throw new Error('explainVolumePixel3d needs a volume-rendered scene');
  const plan = prepareTrace3d(scene);
  const basis = cameraBasis(scene.camera);
  const d = rayDirection(basis, width, height, px, py);
  const jitter = volumeJitter(Math.floor(px), Math.floor(py));
  let span: [number, number] | null = null;
  let dt = 0;
  const runs: { depth: number; samples: number; from: number }[] = [];
  const ray = volumeRay(plan, volumeBounds(plan), volume, basis.origin, d, jitter, {
    span(t0, t1, step) {
      span = [t0, t1];
      dt = step;
    },
    sample(t, depth) {
      const run = runs.at(-1);
      if (run && run.depth === depth) run.samples++;
      else runs.push({ depth, samples: 1, from: t });
    },
  });
  const [linear, alpha] = overBackground(ray, toLinear(scene.background), 1);
  return {
    origin: basis.origin,
    direction: d,
    span,
    dt,
    jitter,
    steps: volume.steps,
    samples: ray.samples,
    runs,
    deepest: runs.reduce((m, r) => Math.max(m, r.depth), 0),
    opacity: 1 - ray.transmittance,
    opticalDepth: ray.opticalDepth,
    exitedEarly: ray.samples < volume.steps && ray.transmittance < EXIT_TRANSMITTANCE,
    colour: [0, 1, 2].map((k) => linearToSrgb(Math.min(1, Math.max(0, linear[k]!)))) as Rgb,
    alpha,
  };
}
