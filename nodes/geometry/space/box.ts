/** Axis-aligned boxes in R³ (the cube seed of the paper's Fig. 24; docs/math-3d.md §7). */
import { sub3, type Vec3 } from './vec3.ts';

/**
 * Signed distance from x to the box with centre c and half-extents h (negative inside):
 * q = |x − c| − h per axis; d = |max(q, 0)| + min(max(q_x, q_y, q_z), 0).
 * Exact outside (the distance to the nearest face, edge or corner) and inside (minus the distance
 * to the nearest face).
 */
export function boxSignedDistance(center: Vec3, halfSize: Vec3, x: Vec3): number {
  const d = sub3(x, center);
  const qx = Math.abs(d[0]) - halfSize[0];
  const qy = Math.abs(d[1]) - halfSize[1];
  const qz = Math.abs(d[2]) - halfSize[2];
  const outside = Math.hypot(Math.max(qx, 0), Math.max(qy, 0), Math.max(qz, 0));
  return outside + Math.min(Math.max(qx, qy, qz), 0);
}
