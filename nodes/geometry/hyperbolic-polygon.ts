/**
 * The regular hyperbolic n-gon with interior angles π/q in the Poincaré disk, centred at 0, as n
 * geodesic mirrors (circles orthogonal to the unit circle). Its reflection group tiles the disk
 * with n-gons, 2q around each vertex.
 *
 * Derivation. Cut the polygon into 2n right triangles O (centre), M (an edge's midpoint), V (a
 * vertex): angle π/n at O, π/(2q) at V (half the interior angle), π/2 at M. In a hyperbolic right
 * triangle, cos A = cosh a · sin B (a the leg opposite A); with A = the angle at V, a = OM:
 *   cosh(OM) = cos(π/(2q)) / sin(π/n).
 * The triangle exists iff the angle sum is below π: π/n + π/(2q) < π/2, i.e. (n − 2)(q − 1) > 2
 * (also: cosh(OM) > 1). In the disk, the geodesic perpendicular to the ray at angle t at hyperbolic
 * distance δ from 0 is the circle with centre coth(δ)·(cos t, sin t) and radius 1/sinh(δ)
 * (orthogonal to the unit circle: centre² = radius² + 1, and it crosses the ray at
 * coth δ − csch δ = tanh(δ/2), the Euclidean radius of hyperbolic distance δ).
 */
import type { Circle } from '../core/values.ts';

/** Whether the n-gon with angles π/q is hyperbolic: (n − 2)(q − 1) > 2 (n ≥ 3, q ≥ 2). */
export const isHyperbolicPolygon = (n: number, q: number): boolean =>
  n >= 3 && q >= 2 && (n - 2) * (q - 1) > 2;

/**
 * The n mirror circles, edge j's midpoint on the ray at angle rotation + 2πj/n. Inside each circle
 * is the side away from the polygon (the tile is outside all of them, inside the unit disk).
 * Caller checks isHyperbolicPolygon first.
 */
export function hyperbolicPolygonMirrors(n: number, q: number, rotation = 0): Circle[] {
  const coshD = Math.cos(Math.PI / (2 * q)) / Math.sin(Math.PI / n);
  const sinhD = Math.sqrt(coshD * coshD - 1);
  const centre = coshD / sinhD;
  const r = 1 / sinhD;
  return Array.from({ length: n }, (_, j) => {
    const t = rotation + (2 * Math.PI * j) / n;
    return { c: [centre * Math.cos(t), centre * Math.sin(t)], r };
  });
}
