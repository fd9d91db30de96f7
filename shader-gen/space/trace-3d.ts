/**
 * The CPU sphere tracer (the tested reference; glsl/trace.glsl.ts is its twin), docs/math-3d.md "§9 The sphere tracer: march, hit, shading":
 * clip the ray to the scene's bounding ball (or a far distance when the orbit is unbounded); then
 * march: walk the point, hit when the seed-image distance is below the tolerance
 * ε(t) = HIT_PIXELS · a · max(t, NEAR·R) (a = angle per pixel), else advance by
 * max(deScale · DE, ε) — DE is safe (never beyond the orbit), ε keeps the march moving where DE
 * is zero or tiny (near the limit set, at inversion centres).
 */
import type { Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { type TracePlan, UNBOUNDED_REACH } from './plan.ts';
import { walk3d, walkResult } from './walk.ts';

/**
 * Hits are decided within this many pixel footprints of a seed image: every surface is drawn this
 * much fatter than it is (a quarter pixel: invisible, and the march still ends in a few steps).
 */
export const HIT_PIXELS = 0.25;
/** ε never falls below the footprint at this fraction of the scene radius (camera inside the scene). */
export const NEAR = 1e-3;

export interface Hit3d {
  readonly hit: boolean;
  /** Ray parameter of the hit (or of where the march stopped). */
  readonly t: number;
  readonly depth: number;
  readonly seed: number;
  /** Final point of the walk at the hit and its factor. */
  readonly final: Vec3;
  readonly factor: number;
  readonly steps: number;
}

/**
 * [t0, t1] of the ray inside the bounds (the scene's, or the volume renderer's), or null when it
 * misses them.
 */
export function rayInterval(
  plan: Pick<TracePlan, 'bounds' | 'bounded'>,
  o: Vec3,
  d: Vec3,
): [number, number] | null {
  const { center: c, radius: r } = plan.bounds;
  const ox = o[0] - c[0];
  const oy = o[1] - c[1];
  const oz = o[2] - c[2];
  if (!plan.bounded) return [0, Math.sqrt(ox * ox + oy * oy + oz * oz) + UNBOUNDED_REACH * r];
  const b = ox * d[0] + oy * d[1] + oz * d[2];
  const disc = b * b - (ox * ox + oy * oy + oz * oz - r * r);
  if (disc <= 0) return null;
  const h = Math.sqrt(disc);
  if (-b + h <= 0) return null;
  return [Math.max(0, -b - h), -b + h];
}

/** The hit tolerance and least step at ray parameter t. */
export const hitTolerance = (plan: TracePlan, angle: number, t: number): number =>
  HIT_PIXELS * angle * Math.max(t, NEAR * plan.bounds.radius);

const MISS: Hit3d = { hit: false, t: 0, depth: 0, seed: -1, final: [0, 0, 0], factor: 1, steps: 0 };

/**
 * Traces the ray o + t·d (d unit) from t = max(tStart, where it enters the bounds); `angle` is the
 * angle per pixel. A reflected ray starts at tStart = the path length so far, from an origin moved
 * back along it by that much, so its hit tolerance keeps growing with the whole path
 * (docs/math-3d.md "Mirror material").
 */
export function traceRay(plan: TracePlan, o: Vec3, d: Vec3, angle: number, tStart = 0): Hit3d {
  const span = plan.scene.seeds.length > 0 ? rayInterval(plan, o, d) : null;
  if (!span) return MISS;
  let t = Math.max(span[0], tStart);
  const w = walkResult();
  for (let i = 0; i < plan.scene.marchSteps; i++) {
    const eps = hitTolerance(plan, angle, t);
    walk3d(plan, o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t, true, w, eps);
    if (w.imageDistance < eps) {
      return {
        hit: true,
        t,
        depth: w.depth,
        seed: w.seed,
        final: [w.x, w.y, w.z],
        factor: w.factor,
        steps: i,
      };
    }
    t += Math.max(plan.scene.deScale * w.de, eps);
    if (t > span[1]) return { ...MISS, t, steps: i };
  }
  return { ...MISS, t, steps: plan.scene.marchSteps };
}
