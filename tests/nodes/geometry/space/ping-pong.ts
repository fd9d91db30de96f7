/** Test helpers for the generators' region rule: region depth, sample points, the ping-pong check. */
import { expect } from 'vitest';
import type { BallSide } from '../../../../nodes/geometry/space/mobius-3d.ts';
import type { Sphere } from '../../../../nodes/geometry/space/sphere.ts';
import { add3, dist3, scale3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';

/** How far x is inside the region (positive inside, negative outside), relative to the radius. */
export const depthIn = (r: BallSide, x: Vec3): number => {
  const d = dist3(x, r.sphere.center) / r.sphere.radius;
  return r.inside ? 1 - d : d - 1;
};
/** A point at radius t·r from a sphere's centre, t ∈ [0, 3]: both sides get sampled. */
export const around = (s: Sphere, dir: Vec3, t: number): Vec3 => add3(s.center, scale3(dir, t * s.radius));

/** Ping-pong: G maps A onto the complement of B (so never into B), the outside of A into B, and G⁻¹ undoes G. */
export function checkPingPong(
  g: { a: BallSide; b: BallSide },
  fwd: (x: Vec3) => { x: Vec3 } | null,
  inv: (x: Vec3) => { x: Vec3 } | null,
  x: Vec3,
) {
  const tol = 1e-7;
  const inA = depthIn(g.a, x);
  if (Math.abs(inA) < 1e-6) return;
  const y = fwd(x);
  if (!y) return;
  if (inA > 0) expect(depthIn(g.b, y.x)).toBeLessThan(tol);
  else expect(depthIn(g.b, y.x)).toBeGreaterThan(-tol);
  const back = inv(y.x);
  expect(dist3(back!.x, x)).toBeLessThan(1e-6 * Math.max(1, dist3(x, [0, 0, 0])));
}
