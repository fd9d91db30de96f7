/**
 * Intersections of lines and circles, for the construction nodes. Each returns the points or the
 * reason there are none; a tangency returns the touching point twice (so both outputs exist).
 */
import type { Circle, Line, Vec2 } from '../core/values.ts';
import { GEOMETRY_EPS } from './circle.ts';
import { add, cross, dist, dot, len, normalize, perp, scale, sub } from './vec.ts';

export type Intersection =
  | { readonly ok: true; readonly points: readonly [Vec2, Vec2] }
  | { readonly ok: false; readonly reason: string };

const none = (reason: string): Intersection => ({ ok: false, reason });
const two = (p: Vec2, q: Vec2): Intersection => ({ ok: true, points: [p, q] });

/** Relative tolerance for "tangent" and "parallel" (tangent points stay usable while dragging). */
const TANGENT_EPS = 1e-9;

/**
 * Lines a1 + t·d1 and a2 + u·d2 meet where t = ((a2 − a1) × d2)/(d1 × d2); parallel when
 * d1 × d2 ≈ 0 (relative to |d1||d2|). The single point is returned twice.
 */
export function intersectLines(l1: Line, l2: Line): Intersection {
  const d1 = sub(l1.b, l1.a);
  const d2 = sub(l2.b, l2.a);
  const den = cross(d1, d2);
  if (Math.abs(den) <= GEOMETRY_EPS * len(d1) * len(d2)) {
    const offset = Math.abs(cross(sub(l2.a, l1.a), normalize(d1)));
    return none(
      offset <= GEOMETRY_EPS * Math.max(1, len(l1.a))
        ? 'the lines coincide: every point is common, there is no single intersection'
        : 'the lines are parallel: they do not meet',
    );
  }
  const p = add(l1.a, scale(d1, cross(sub(l2.a, l1.a), d2) / den));
  return two(p, p);
}

/**
 * Line a + t·u (u unit, from a towards b) and circle (c, r): the foot of the perpendicular from c
 * is m = a + ((c − a)·u) u, at distance h0 = |m − c|; with h² = r² − h0² the points are m ∓ h·u,
 * in the line's direction (p1 first). h² < 0 → no intersection.
 */
export function intersectLineCircle(line: Line, circle: Circle): Intersection {
  const u = normalize(sub(line.b, line.a));
  const m = add(line.a, scale(u, dot(sub(circle.c, line.a), u)));
  const h2 = circle.r * circle.r - dot(sub(m, circle.c), sub(m, circle.c));
  const tol = TANGENT_EPS * circle.r * circle.r;
  if (h2 < -tol) return none('the line misses the circle: no intersection');
  const h = Math.sqrt(Math.max(0, h2 <= tol ? 0 : h2));
  return two(sub(m, scale(u, h)), add(m, scale(u, h)));
}

/**
 * Circles (c1, r1), (c2, r2), d = |c2 − c1|: along u = (c2 − c1)/d the common chord sits at
 * a = (d² + r1² − r2²)/(2d) from c1, half-length h = √(r1² − a²). p1 = c1 + a·u − h·perp(u) (right
 * of c1 → c2), p2 = c1 + a·u + h·perp(u) (left). None when d > r1 + r2 or d < |r1 − r2|.
 */
export function intersectCircles(k1: Circle, k2: Circle): Intersection {
  const d = dist(k1.c, k2.c);
  const size = Math.max(k1.r, k2.r);
  if (d <= GEOMETRY_EPS * Math.max(1, size)) {
    return none(
      Math.abs(k1.r - k2.r) <= GEOMETRY_EPS * size
        ? 'the circles are the same: every point is common'
        : 'the circles are concentric: they do not meet',
    );
  }
  const u = scale(sub(k2.c, k1.c), 1 / d);
  const a = (d * d + k1.r * k1.r - k2.r * k2.r) / (2 * d);
  const h2 = k1.r * k1.r - a * a;
  const tol = TANGENT_EPS * size * size;
  if (h2 < -tol) {
    return none(
      d > k1.r + k2.r
        ? 'the circles lie apart: they do not meet'
        : 'one circle lies inside the other: they do not meet',
    );
  }
  const h = h2 <= tol ? 0 : Math.sqrt(h2);
  const m = add(k1.c, scale(u, a));
  const n = perp(u);
  return two(sub(m, scale(n, h)), add(m, scale(n, h)));
}
