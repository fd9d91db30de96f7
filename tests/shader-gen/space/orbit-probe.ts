/**
 * Probing a ball for drawn orbit points with the IIS's own hit test (a point is drawn when its walk
 * ends inside a seed): the check of the tracer bound where brute-force orbit spheres are not
 * available (overlapping mirrors, the pseudo-Kleinian's non-discrete group).
 */
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { sampleSpace } from '../../../nodes/core/seed-3d.ts';
import { add3, scale3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';

/** Directions for probing a ball: a fixed, well-spread set (golden-spiral points). */
export const PROBES: Vec3[] = Array.from({ length: 400 }, (_, k) => {
  const z = 1 - (2 * (k + 0.5)) / 400;
  const a = k * Math.PI * (3 - Math.sqrt(5));
  const h = Math.sqrt(1 - z * z);
  return [h * Math.cos(a), h * Math.sin(a), z];
});

/** Shell radii, as fractions of the bound: inside it up to 0.99, then beyond it up to 10. */
export const SHELLS = [0.1, 0.25, 0.4, 0.55, 0.7, 0.85, 0.99, 1.5, 2, 3, 4, 6, 8, 10];

/** The smallest shell radius ρ (× de) whose probe points meet the orbit, else ∞. */
export function orbitWithin(scene: Scene3d, x: Vec3, de: number): number {
  const deep = { ...scene, maxIterations: 200 };
  for (const rho of SHELLS) {
    for (const p of PROBES) {
      const s = sampleSpace(deep, add3(x, scale3(p, rho * de)));
      if (s.escaped && s.distance !== null && s.distance < 0) return rho;
    }
  }
  return Number.POSITIVE_INFINITY;
}
