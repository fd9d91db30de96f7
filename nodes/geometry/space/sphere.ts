/**
 * Spheres, planes and their inversions in R³ (docs/math-3d.md §1–§2). Pure functions; failures
 * are typed results with a message for the node, never NaN.
 */
import { add3, cross3, dist3, dot3, len2v3, len3, normalize3, scale3, sub3, type Vec3 } from './vec3.ts';

/** Relative tolerance for "coplanar", "same point", "through the centre" decisions. */
export const SPACE_EPS = 1e-9;

/** A sphere; its region is the open ball |x − center| < radius. */
export interface Sphere {
  readonly center: Vec3;
  readonly radius: number;
}

/**
 * A plane through `point` with unit `normal`. A plane mirror KEEPS the side its normal points to
 * ((x − point)·normal > 0) and moves the other side (the 2D line's kept left side, one dimension up).
 */
export interface Plane {
  readonly point: Vec3;
  readonly normal: Vec3;
}

export type Result<T> =
  | { readonly ok: true; readonly value: T }
  | { readonly ok: false; readonly error: string };
export const ok = <T>(value: T): Result<T> => ({ ok: true, value });
export const fail = <T>(error: string): Result<T> => ({ ok: false, error });

/** A point together with the conformal factor (|Jacobian|^(1/3), the local length scale) of the map that produced it. */
export interface Mapped {
  readonly x: Vec3;
  readonly factor: number;
}

/**
 * Sphere inversion I_S(x) = c + r²(x − c)/|x − c|², conformal (length) factor r²/|x − c|²
 * (paper §2.2). x = c has no finite image: null.
 */
export function invertInSphere(s: Sphere, x: Vec3): Mapped | null {
  const d = sub3(x, s.center);
  const l2 = len2v3(d);
  if (l2 === 0) return null;
  const k = (s.radius * s.radius) / l2;
  return { x: add3(s.center, scale3(d, k)), factor: k };
}

/** Signed distance (x − q)·n: negative on the side the plane mirror moves. */
export const planeSignedDistance = (p: Plane, x: Vec3): number => dot3(sub3(x, p.point), p.normal);

/** Plane reflection ρ(x) = x − 2((x − q)·n) n, factor 1. */
export function reflectInPlane(p: Plane, x: Vec3): Mapped {
  return { x: sub3(x, scale3(p.normal, 2 * planeSignedDistance(p, x))), factor: 1 };
}

/** Whether x is in the open ball of s. */
export const insideSphere = (s: Sphere, x: Vec3): boolean => dist3(x, s.center) < s.radius;

/**
 * Image of sphere S = (c, r) under inversion in T = (c₂, r₂) (docs/math-3d.md §1):
 * δ = |c − c₂|² − r², k = r₂²/δ, c' = c₂ + k(c − c₂), r' = |k| r. δ = 0 (S passes through c₂):
 * the image is the plane through c₂ + (r₂²/(2|c − c₂|²))(c − c₂) with normal −(c − c₂)/|c − c₂|, so
 * that its region (the side a plane mirror moves, (x − q)·n < 0) is the image of S's ball.
 */
export function invertSphere(
  inT: Sphere,
  s: Sphere,
): { readonly kind: 'sphere'; readonly sphere: Sphere } | { readonly kind: 'plane'; readonly plane: Plane } {
  const d = sub3(s.center, inT.center);
  const dd = len2v3(d);
  const delta = dd - s.radius * s.radius;
  if (Math.abs(delta) <= SPACE_EPS * Math.max(1, dd, s.radius * s.radius)) {
    // The point of S farthest from c₂ is c₂ + 2d; its image is at distance r₂²/(2|d|) along d.
    const foot = add3(inT.center, scale3(d, (inT.radius * inT.radius) / (2 * dd)));
    // S's ball maps to the far side of the plane (away from c₂): that side is the region.
    return { kind: 'plane', plane: { point: foot, normal: scale3(normalize3(d), -1) } };
  }
  const k = (inT.radius * inT.radius) / delta;
  return {
    kind: 'sphere',
    sphere: { center: add3(inT.center, scale3(d, k)), radius: Math.abs(k) * s.radius },
  };
}

/**
 * Circumsphere of four points: the centre c solves 2(pᵢ − p₀)·c = |pᵢ|² − |p₀|², i = 1..3
 * (Cramer's rule on the rows u, v, w = pᵢ − p₀, after translating p₀ to the origin:
 * c − p₀ = (|u|² (v × w) + |v|² (w × u) + |w|² (u × v)) / (2 u·(v × w))); r = |p₀ − c|.
 * Coplanar or coincident points (u·(v × w) ≈ 0 relative to the spread) → a typed failure.
 */
export function sphereFromFourPoints(a: Vec3, b: Vec3, c: Vec3, d: Vec3): Result<Sphere> {
  const u = sub3(b, a);
  const v = sub3(c, a);
  const w = sub3(d, a);
  const size = Math.max(len3(u), len3(v), len3(w));
  if (size === 0) return fail('the four points coincide: no sphere passes through them');
  const det = dot3(u, cross3(v, w));
  if (Math.abs(det) <= SPACE_EPS * size ** 3) {
    return fail('the four points are coplanar (or some coincide): no single sphere passes through them');
  }
  const num = add3(
    add3(scale3(cross3(v, w), len2v3(u)), scale3(cross3(w, u), len2v3(v))),
    scale3(cross3(u, v), len2v3(w)),
  );
  const off = scale3(num, 1 / (2 * det));
  return ok({ center: add3(a, off), radius: len3(off) });
}

/**
 * Sphere(P, P', P'', Q) of the paper's §5.1.2 (Fig. 20): P' = I_S1(P) and P'' = I_S2(P) are the
 * inversions of the control point P in S1 and S2, and the result is the sphere through P, P', P'', Q.
 * Because it passes through P and I_S1(P) (on the ray from c1), the power of c1 with respect to it is
 * |c1 − P|·|c1 − P'| = r1²: it is orthogonal to S1, and likewise to S2 (docs/math-3d.md §3).
 * Fails when P is a centre, or when the four points are coplanar (e.g. P on the line of centres).
 */
export function sphereThroughInverses(s1: Sphere, s2: Sphere, p: Vec3, q: Vec3): Result<Sphere> {
  const p1 = invertInSphere(s1, p);
  const p2 = invertInSphere(s2, p);
  if (!p1 || !p2) return fail('the control point P sits on a sphere centre: P′ or P″ is at infinity');
  const s = sphereFromFourPoints(p, p1.x, p2.x, q);
  return s.ok ? s : fail(`Sphere(P, P′, P″, Q): ${s.error}`);
}
