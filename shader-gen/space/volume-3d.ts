/**
 * The CPU volume renderer of the nesting depth (the tested reference; glsl/volume.glsl.ts is its
 * twin), docs/math-3d.md "§11 Volume rendering of the nesting depth" (paper §4.2, Fig. 10). Along the
 * ray's span inside the ball holding every element region, N = steps samples
 *   t_i = t0 + (i + j)·Δt,  Δt = (t1 − t0)/N,  j ∈ [0, 1) a hash of the pixel (no banding, CPU = GPU),
 * each the walk's depth k → transfer (σ(k), u(k)) (extinction, palette place); composited
 * front to back:  α_i = 1 − e^(−σ_i Δt),  C += T·α_i·colour_i,  T ← T·(1 − α_i),  stopping once
 * T < EXIT_TRANSMITTANCE. The optical depth τ = Σ σ_i Δt approximates ∫ σ dt (T = e^(−τ)).
 */
import type { Sphere, Volume3d } from '../../nodes/core/scene-3d.ts';
import type { Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { cosinePalette } from '../colour.ts';
import { type Rgb, toLinear } from '../srgb.ts';
import { boundedRegions, enclosingBall, type TracePlan } from './plan.ts';
import { rayInterval } from './trace-3d.ts';
import { walkDepth3d } from './walk.ts';

/** Compositing stops once the transmittance is below this (the ray is ≈ 99 % opaque). */
export const EXIT_TRANSMITTANCE = 0.01;

/** Where the depth can be positive: a ball holding every element region, or the tracer's far span. */
export interface VolumeBounds {
  readonly bounds: Sphere;
  readonly bounded: boolean;
}

/**
 * The element regions' enclosing ball when every region is a bounded ball (depth ≥ 1 only inside a
 * region), else the tracer's bounds, unbounded; null without elements (every depth is 0).
 */
export function volumeBounds(plan: TracePlan): VolumeBounds | null {
  if (plan.scene.elements.length === 0) return null;
  const regions = plan.scene.elements.map(boundedRegions);
  if (regions.some((r) => r === null)) return { bounds: plan.bounds, bounded: false };
  return { bounds: enclosingBall(regions.flatMap((r) => r ?? [])), bounded: true };
}

/** lowbias32 (Wellons): x ^= x≫16, x ·= 0x7feb352d, x ^= x≫15, x ·= 0x846ca68b, x ^= x≫16, mod 2³². */
export function hash32(x: number): number {
  let h = (x ^ (x >>> 16)) >>> 0;
  h = Math.imul(h, 0x7feb352d) >>> 0;
  h = (h ^ (h >>> 15)) >>> 0;
  h = Math.imul(h, 0x846ca68b) >>> 0;
  return (h ^ (h >>> 16)) >>> 0;
}

/** The sample offset j ∈ [0, 1) of pixel (ix, iy): the top 24 bits of hash(ix + hash(iy)), exact in float32. */
export const volumeJitter = (ix: number, iy: number): number =>
  (hash32((ix + hash32(iy >>> 0)) >>> 0) >>> 8) / 16777216;

/** The palette place u(k) = (k' − depthFrom + 1)/(depthTo − depthFrom + 1), k' = min(k, depthTo). */
export const transferPlace = (v: Volume3d, depth: number): number =>
  (Math.min(depth, v.depthTo) - v.depthFrom + 1) / (v.depthTo - v.depthFrom + 1);

/** The extinction σ(k) = density·growth^(min(k, depthTo) − depthFrom) for k ≥ depthFrom, else 0. */
export const extinction = (v: Volume3d, depth: number): number =>
  depth < v.depthFrom ? 0 : v.density * v.growth ** (Math.min(depth, v.depthTo) - v.depthFrom);

/** The emitted colour at transfer u: the cosine palette at u, in linear light. */
export const volumeColour = (v: Volume3d, u: number): Rgb => toLinear(cosinePalette(v.a, v.b, v.c, v.d, u));

export interface VolumeRay {
  /** Σ T·α·colour: the premultiplied colour of the medium, linear light. */
  readonly rgb: Rgb;
  /** What is left for the background: e^(−τ) (below EXIT_TRANSMITTANCE: the ray stopped). */
  readonly transmittance: number;
  /** τ = Σ σ_i Δt over the samples taken. */
  readonly opticalDepth: number;
  /** Samples taken (fewer than `steps` when the ray became opaque). */
  readonly samples: number;
}

const EMPTY: VolumeRay = { rgb: [0, 0, 0], transmittance: 1, opticalDepth: 0, samples: 0 };

/**
 * Watches one ray's integration (Explain this pixel, shader-gen/space/explain-volume-3d.ts): `span`
 * once, with the ray's interval in the bounds and Δt (not called when the ray misses them), then
 * `sample` for every sample taken — its t, its depth k, and the transmittance T after it.
 */
export interface VolumeObserver {
  span(t0: number, t1: number, dt: number): void;
  sample(t: number, depth: number, transmittance: number): void;
}

/**
 * Integrates the ray o + t·d (d unit) through the nesting depth with sample offset `jitter`; the
 * observer, when given, sees each sample (the render passes none).
 */
export function volumeRay(
  plan: TracePlan,
  vb: VolumeBounds | null,
  v: Volume3d,
  o: Vec3,
  d: Vec3,
  jitter: number,
  observer?: VolumeObserver,
): VolumeRay {
  const span = vb ? rayInterval(vb, o, d) : null;
  if (!span) return EMPTY;
  const n = v.steps;
  const dt = (span[1] - span[0]) / n;
  observer?.span(span[0], span[1], dt);
  const rgb: Rgb = [0, 0, 0];
  let T = 1;
  let tau = 0;
  // The colour depends on the depth alone: recomputed only when the depth changes.
  let lastDepth = -1;
  let c: Rgb = [0, 0, 0];
  for (let i = 0; i < n; i++) {
    const t = span[0] + (i + jitter) * dt;
    const depth = walkDepth3d(plan, o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t);
    if (depth < v.depthFrom) {
      observer?.sample(t, depth, T);
      continue;
    }
    const sigma = extinction(v, depth) * dt;
    tau += sigma;
    const alpha = 1 - Math.exp(-sigma);
    if (depth !== lastDepth) {
      c = volumeColour(v, transferPlace(v, depth));
      lastDepth = depth;
    }
    for (let k = 0; k < 3; k++) rgb[k]! += T * alpha * c[k]!;
    T *= 1 - alpha;
    observer?.sample(t, depth, T);
    if (T < EXIT_TRANSMITTANCE) return { rgb, transmittance: T, opticalDepth: tau, samples: i + 1 };
  }
  return { rgb, transmittance: T, opticalDepth: tau, samples: n };
}

/**
 * The ray's colour over the background (linear `bg`, alpha `bgAlpha`) as straight (not
 * premultiplied) RGB and alpha a = 1 − T + T·bgAlpha — what the GPU's renderSample returns.
 */
export function overBackground(r: VolumeRay, bg: readonly number[], bgAlpha: number): [Rgb, number] {
  const a = 1 - r.transmittance + r.transmittance * bgAlpha;
  const keep = r.transmittance * bgAlpha;
  const c = (k: number) => (a > 0 ? (r.rgb[k]! + keep * bg[k]!) / a : bg[k]!);
  return [[c(0), c(1), c(2)], a];
}
