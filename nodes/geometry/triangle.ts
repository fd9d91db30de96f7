/**
 * Triangle groups (p, q, r): the three mirrors of the triangle with angles π/p (at 0), π/q (on
 * the x-axis) and π/r (on line 2), as in docs/math.md. q or r may be ∞ (written 0): cos(π/∞) = 1.
 */
import type { Vec2 } from '../core/values.ts';
import { cosPiOver, sinPiOver } from './angles.ts';

export type TriangleGeometry = 'spherical' | 'euclidean' | 'hyperbolic';

export interface TriangleMirrors {
  readonly geometry: TriangleGeometry;
  /** Line 1: through 0, inside y < 0. Line 2: through 0 at angle π/p, n = (sin π/p, −cos π/p). */
  readonly line1: { q: Vec2; n: Vec2 };
  readonly line2: { q: Vec2; n: Vec2 };
  /** Mirror 3: a circle (hyperbolic, spherical) or a line (Euclidean). */
  readonly mirror3: { kind: 'circle'; c: Vec2; r: number } | { kind: 'line'; q: Vec2; n: Vec2 };
}

/** 1/n with ∞ written as 0. */
const inv = (n: number) => (n === 0 ? 0 : 1 / n);

export function triangleGeometry(p: number, q: number, r: number): TriangleGeometry {
  const s = inv(p) + inv(q) + inv(r);
  if (Math.abs(s - 1) < 1e-12) return 'euclidean';
  return s > 1 ? 'spherical' : 'hyperbolic';
}

/**
 * u = (ux, uy), uy = cos π/q, ux = (cos π/r + cos π/p cos π/q)/sin π/p. Hyperbolic/spherical:
 * R² = κ/(|u|² − 1), κ = ±1, circle centre R·u, radius R. Euclidean: |u| = 1 and mirror 3 is
 * the line p·u = size with inside p·u > size.
 */
export function triangleMirrors(p: number, q: number, r: number, size = 1): TriangleMirrors {
  const cp = cosPiOver(p);
  const sp = sinPiOver(p);
  const cq = cosPiOver(q);
  const cr = cosPiOver(r);
  const uy = cq;
  const ux = (cr + cp * cq) / sp;
  const geometry = triangleGeometry(p, q, r);
  const line1 = { q: [0, 0] as Vec2, n: [0, 1] as Vec2 };
  const line2 = { q: [0, 0] as Vec2, n: [sp, -cp] as Vec2 };
  if (geometry === 'euclidean') {
    const l = Math.hypot(ux, uy);
    const u: Vec2 = [ux / l, uy / l];
    return {
      geometry,
      line1,
      line2,
      mirror3: { kind: 'line', q: [u[0] * size, u[1] * size], n: [-u[0], -u[1]] },
    };
  }
  const kappa = geometry === 'hyperbolic' ? 1 : -1;
  const R = Math.sqrt(kappa / (ux * ux + uy * uy - 1));
  return { geometry, line1, line2, mirror3: { kind: 'circle', c: [R * ux, R * uy], r: R } };
}
