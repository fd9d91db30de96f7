/**
 * Two-circle Möbius generators g = σ_C2∘σ_C1 (docs/math.md "Two-circle Möbius generator"): their type
 * (from the real trace τ) and the regions A (where g applies) and B = g(complement of A).
 */
import type { DiskRegion } from '../core/scene-elements.ts';
import type { Circle, Vec2 } from '../core/values.ts';
import { GEOMETRY_EPS, invertCircle, invertPoint } from './circle.ts';
import { dist } from './vec.ts';

export type MobiusType = 'hyperbolic' | 'parabolic' | 'elliptic';

export interface MobiusClass {
  readonly type: MobiusType;
  /** τ = (r1² + r2² − d²)/(r1 r2). */
  readonly trace: number;
  /** Elliptic only: crossing angle θ (cos θ = τ/2); g rotates by 2θ. */
  readonly angle?: number;
}

const TANGENT_EPS = 1e-9;

export const sameCircle = (a: Circle, b: Circle): boolean =>
  dist(a.c, b.c) <= GEOMETRY_EPS * Math.max(1, a.r) && Math.abs(a.r - b.r) <= GEOMETRY_EPS * Math.max(1, a.r);

/** Type of σ_C2∘σ_C1: disjoint or nested → hyperbolic, tangent → parabolic, crossing → elliptic. */
export function classifyTwoCircle(c1: Circle, c2: Circle): MobiusClass {
  const d = dist(c1.c, c2.c);
  const trace = (c1.r * c1.r + c2.r * c2.r - d * d) / (c1.r * c2.r);
  if (Math.abs(Math.abs(trace) - 2) <= TANGENT_EPS * Math.max(1, Math.abs(trace)))
    return { type: 'parabolic', trace };
  if (Math.abs(trace) > 2) return { type: 'hyperbolic', trace };
  return { type: 'elliptic', trace, angle: Math.acos(trace / 2) };
}

export type TwoCircleRegions =
  | { ok: true; a: DiskRegion; b: DiskRegion; c1Image: Circle; tiling: boolean }
  | { ok: false; reason: string };

/**
 * A = inside C1, except when C2 lies inside C1 (d + r2 ≤ r1), where A = outside C1 (else the tile
 * would be empty). B is the side of C1' = σ_C2(C1) holding g(x) for x outside A: g(∞) = σ_C2(c1)
 * when A = inside C1 (∞ is outside A), and g(c1) = σ_C2(∞) = c2 when A = outside C1.
 */
export function twoCircleRegions(c1: Circle, c2: Circle): TwoCircleRegions {
  if (sameCircle(c1, c2))
    return { ok: false, reason: 'the two circles are the same: the map is the identity' };
  const image = invertCircle(c2, c1);
  if (!image) {
    return { ok: false, reason: "C1 passes through C2's centre, so its image C1' is a line: move C1 or C2" };
  }
  const d = dist(c1.c, c2.c);
  const aOutside = d + c2.r <= c1.r;
  let witness: Vec2 | null;
  if (aOutside) witness = c2.c;
  else witness = invertPoint(c2, c1.c); // null when concentric: g(∞) = ∞, outside C1'
  const bOutside = witness === null ? true : dist(witness, image.c) > image.r;
  const cls = classifyTwoCircle(c1, c2);
  let tiling = true;
  if (cls.type === 'elliptic' && cls.angle !== undefined) {
    const n1 = Math.PI / cls.angle;
    const n2 = Math.PI / (Math.PI - cls.angle);
    tiling = Math.abs(n1 - Math.round(n1)) < 1e-6 || Math.abs(n2 - Math.round(n2)) < 1e-6;
  }
  return {
    ok: true,
    a: { c: c1.c, r: c1.r, outside: aOutside },
    b: { c: image.c, r: image.r, outside: bOutside },
    c1Image: image,
    tiling,
  };
}
