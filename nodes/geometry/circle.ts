/** Circles, lines and inversions: the constructions the node types resolve on the CPU. */
import type { Circle, Line, Vec2 } from '../core/values.ts';
import { add, cross, dist, dot, len2, normalize, perp, scale, sub } from './vec.ts';

/** Relative tolerance for "collinear", "tangent", "same point" decisions. */
export const GEOMETRY_EPS = 1e-9;

/** σ_C(p) = c + r²(p−c)/|p−c|² (undefined at p = c: returns null). */
export function invertPoint(circle: Circle, p: Vec2): Vec2 | null {
  const d = sub(p, circle.c);
  const l2 = len2(d);
  if (l2 === 0) return null;
  return add(circle.c, scale(d, (circle.r * circle.r) / l2));
}

/**
 * Image of circle C1 under inversion in C2 (docs/math.md): δ = |c1−c2|² − r1², k = r2²/δ,
 * c1' = c2 + k(c1−c2), r1' = |k| r1. δ = 0 (C1 through c2) → the image is a line: null.
 */
export function invertCircle(inC2: Circle, c1: Circle): Circle | null {
  const d = sub(c1.c, inC2.c);
  const delta = len2(d) - c1.r * c1.r;
  if (Math.abs(delta) <= GEOMETRY_EPS * Math.max(1, len2(d), c1.r * c1.r)) return null;
  const k = (inC2.r * inC2.r) / delta;
  return { c: add(inC2.c, scale(d, k)), r: Math.abs(k) * c1.r };
}

/**
 * Circle through three points: the centre solves |c−a| = |c−b| = |c−p3|, i.e. with
 * u = b−a, v = p3−a, D = 2(u × v): c = a + (|u|² perp-ish terms)/D. Collinear (D ≈ 0) → null.
 */
export function circleThrough3(a: Vec2, b: Vec2, c: Vec2): Circle | null {
  const u = sub(b, a);
  const v = sub(c, a);
  const D = 2 * cross(u, v);
  const size = Math.max(len2(u), len2(v));
  if (Math.abs(D) <= GEOMETRY_EPS * size || size === 0) return null;
  const uu = len2(u);
  const vv = len2(v);
  const center: Vec2 = [a[0] + (v[1] * uu - u[1] * vv) / D, a[1] + (u[0] * vv - v[0] * uu) / D];
  return { c: center, r: dist(center, a) };
}

/** Unit normal of the kept (left) side of a → b: n = perp(d), d = (b−a)/|b−a|. */
export function lineNormal(line: Line): Vec2 {
  return perp(normalize(sub(line.b, line.a)));
}

/** Whether a line's two defining points coincide (no direction). */
export const isDegenerateLine = (line: Line): boolean =>
  dist(line.a, line.b) <= GEOMETRY_EPS * Math.max(1, Math.hypot(...line.a));

/** Reflection in the line through q with unit normal n: ρ(p) = p − 2((p−q)·n) n. */
export function reflectPoint(q: Vec2, n: Vec2, p: Vec2): Vec2 {
  return sub(p, scale(n, 2 * dot(sub(p, q), n)));
}

/** Signed distance (p−q)·n: negative on the reflected (inside) side. */
export const signedDistance = (q: Vec2, n: Vec2, p: Vec2): number => dot(sub(p, q), n);
