/**
 * Mirror material and environment on the CPU (the reference; glsl/reflect.glsl.ts is its twin),
 * docs/math-3d.md "Mirror material":
 *   environment — what a ray of direction d (unit) that hits nothing sees: flat, the background B;
 *                 sky, mix(H, B, √d_z) above the horizon and below it a checkered ground
 *                 G·(1 − ½√s)·(1 − ½·c·min(1, 4s)), s = −d_z, c = (⌊d_x/s⌋ + ⌊d_y/s⌋) mod 2 (the
 *                 squares of a plane one unit below, faded towards the horizon where they would
 *                 alias), H horizon, G ground, all in linear light;
 *   reflection  — at a hit on a seed image of reflectivity r (Fresnel's F0) with normal n:
 *                 F = r + (1 − r)(1 − cos θ)^5, cos θ = max(−d·n, 0) (Schlick);
 *                 colour = (1 − F)·matte + F·base ⊙ colour(reflected ray),
 *                 reflected ray d' = d − 2(d·n)n from p + 2ε n, traced by the same sphere tracer;
 *   bound       — at most `reflections` bounces (the last hit is shaded matte), so 0 is matte.
 */
import { DEFAULT_REFLECTIONS, type Environment3d, type Scene3d } from '../../nodes/core/scene-3d.ts';
import { add3, dot3, normalize3, scale3, sub3, type Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { type Rgb, toLinear } from '../srgb.ts';
import type { TracePlan } from './plan.ts';
import { shadeHit, surfaceAt } from './shade-3d.ts';
import { type Hit3d, traceRay } from './trace-3d.ts';

/** The linear colour seen in direction d (unit) by a ray that hits nothing. */
export type Environment = (d: Vec3) => Rgb;

const mix = (a: Rgb, b: Rgb, k: number): Rgb => [
  a[0] + (b[0] - a[0]) * k,
  a[1] + (b[1] - a[1]) * k,
  a[2] + (b[2] - a[2]) * k,
];

/** The scene's environment, its colours converted to linear light once. */
export function environmentOf(scene: Scene3d): Environment {
  const zenith = toLinear(scene.background);
  const env: Environment3d = scene.environment ?? { mode: 'flat' };
  if (env.mode === 'flat') return () => zenith;
  const horizon = toLinear(env.horizon);
  const ground = toLinear(env.ground);
  return (d) => {
    if (d[2] >= 0) return mix(horizon, zenith, Math.sqrt(d[2]));
    const s = -d[2];
    const c = (Math.floor(d[0] / s) + Math.floor(d[1] / s)) & 1;
    const k = (1 - 0.5 * Math.sqrt(s)) * (1 - 0.5 * c * Math.min(1, 4 * s));
    return [ground[0] * k, ground[1] * k, ground[2] * k];
  };
}

/** Schlick's Fresnel term F = r + (1 − r)(1 − cos θ)^5. */
export const fresnel = (r: number, cos: number): number => r + (1 - r) * (1 - cos) ** 5;

/** d reflected about the unit normal n: d − 2(d·n)n. */
export const reflect3 = (d: Vec3, n: Vec3): Vec3 => sub3(d, scale3(n, 2 * dot3(d, n)));

/** The bounces a scene allows (its reflections, or the default). */
export const reflectionsOf = (scene: Scene3d): number => scene.reflections ?? DEFAULT_REFLECTIONS;

/** Whether any seed is a mirror (the shader then carries the reflection loop). */
export const hasMirrors = (scene: Scene3d): boolean => scene.seeds.some((s) => s.reflectivity !== undefined);

/**
 * Linear colour of the ray o + t·d whose first trace is `hit` (angle per pixel `angle`): matte
 * shading, mirrors reflecting up to the scene's bound, the environment where a ray escapes.
 */
export function radiance(
  plan: TracePlan,
  env: Environment,
  o: Vec3,
  d: Vec3,
  angle: number,
  hit: Hit3d,
): Rgb {
  const depth = reflectionsOf(plan.scene);
  const colour: Rgb = [0, 0, 0];
  let weight: Rgb = [1, 1, 1];
  const add = (c: Rgb, k: number) => {
    for (let i = 0; i < 3; i++) colour[i]! += weight[i]! * k * c[i]!;
  };
  let from = o;
  let dir = d;
  let h = hit;
  for (let bounce = 0; ; bounce++) {
    if (!h.hit) {
      add(env(dir), 1);
      return colour;
    }
    const surface = surfaceAt(plan, from, dir, angle, h);
    const matte = shadeHit(plan, from, dir, angle, h, surface);
    const r = plan.scene.seeds[h.seed]!.reflectivity ?? 0;
    if (bounce >= depth || !(r > 0)) {
      add(matte, 1);
      return colour;
    }
    const { p, n, base, eps } = surface;
    const F = fresnel(r, Math.min(1, Math.max(0, -dot3(dir, n))));
    add(matte, 1 - F);
    weight = [weight[0] * F * base[0], weight[1] * F * base[1], weight[2] * F * base[2]];
    // Continue the path: the reflected ray's origin is moved back by the path length t so far,
    // and its march starts at t, so its tolerance ε(t) keeps growing along the whole path.
    dir = normalize3(reflect3(dir, n));
    from = sub3(add3(p, scale3(n, 2 * eps)), scale3(dir, h.t));
    h = traceRay(plan, from, dir, angle, h.t);
  }
}
