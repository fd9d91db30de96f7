/**
 * Two-sphere Möbius generator G = I_S2 ∘ I_S1 (I_S1 first), mapping S1 onto S1' = I_S2(S1)
 * (paper §5.1.2, Fig. 19; docs/math-3d.md §2). The 2D two-circle rule with balls for disks.
 */
import {
  fail,
  insideSphere,
  invertInSphere,
  invertSphere,
  type Mapped,
  ok,
  type Result,
  SPACE_EPS,
  type Sphere,
} from './sphere.ts';
import { dist3, type Vec3 } from './vec3.ts';

/** One side of a sphere: its open ball (inside = true) or the open outside. */
export interface BallSide {
  readonly sphere: Sphere;
  readonly inside: boolean;
}

export const inSide = (r: BallSide, x: Vec3): boolean => {
  const d = dist3(x, r.sphere.center);
  return r.inside ? d < r.sphere.radius : d > r.sphere.radius;
};

export type Mobius3dType = 'hyperbolic' | 'parabolic' | 'elliptic';

export interface Mobius3d {
  readonly s1: Sphere;
  readonly s2: Sphere;
  /** S1' = I_S2(S1). */
  readonly s1Image: Sphere;
  /** A: the region G acts on. */
  readonly a: BallSide;
  /** B = G(complement of A): the region G⁻¹ acts on. */
  readonly b: BallSide;
  readonly type: Mobius3dType;
}

/**
 * Type from the spheres' centre distance d: apart (d > r1 + r2) or nested (d < |r1 − r2|) →
 * hyperbolic; kissing (d = r1 + r2 or d = |r1 − r2|) → parabolic; crossing → elliptic (a rotation
 * about their circle of intersection by twice the crossing angle). Two spheres never give a loxodromic map.
 */
export function classifyTwoSpheres(s1: Sphere, s2: Sphere): Mobius3dType {
  const d = dist3(s1.center, s2.center);
  const tol = SPACE_EPS * Math.max(1, s1.radius, s2.radius, d);
  const outer = d - (s1.radius + s2.radius);
  const inner = Math.abs(s1.radius - s2.radius) - d;
  if (Math.abs(outer) <= tol || Math.abs(inner) <= tol) return 'parabolic';
  return outer > 0 || inner > 0 ? 'hyperbolic' : 'elliptic';
}

/**
 * Builds the generator and its regions (docs/math-3d.md §2). A = inside S1, except when S2 lies
 * inside S1 (then A = outside S1, else the tile would be empty). Since I_S1 swaps the two sides of S1,
 * G(complement of A) = I_S2(A), so B is the side of S1' with B.inside = A.inside XOR (c2 ∈ ball S1):
 * nested (c2 inside S1 ⊂ S2) gives "inside S1 → G, outside S1' → G⁻¹"; disjoint gives
 * "inside S1 → G, inside S1' → G⁻¹". Fails when S1 = S2 (identity) or S1 passes through c2 (S1' a plane).
 */
export function mobius3d(s1: Sphere, s2: Sphere): Result<Mobius3d> {
  const d = dist3(s1.center, s2.center);
  const scaleLen = Math.max(1, s1.radius, s2.radius);
  if (d <= SPACE_EPS * scaleLen && Math.abs(s1.radius - s2.radius) <= SPACE_EPS * scaleLen) {
    return fail('S1 and S2 are the same sphere: the generator is the identity');
  }
  const img = invertSphere(s2, s1);
  if (img.kind === 'plane') return fail("S1 passes through the centre of S2: its image S1' is a plane");
  const s2InsideS1 = d + s2.radius <= s1.radius;
  const a: BallSide = { sphere: s1, inside: !s2InsideS1 };
  const c2InS1 = insideSphere(s1, s2.center);
  const b: BallSide = { sphere: img.sphere, inside: a.inside !== c2InS1 };
  return ok({ s1, s2, s1Image: img.sphere, a, b, type: classifyTwoSpheres(s1, s2) });
}

/** Applies inversions in order, multiplying their factors; null if a point hits a centre. */
export function invertChain(spheres: readonly Sphere[], x: Vec3): Mapped | null {
  let p = x;
  let factor = 1;
  for (const s of spheres) {
    const m = invertInSphere(s, p);
    if (!m) return null;
    p = m.x;
    factor *= m.factor;
  }
  return { x: p, factor };
}

/** G(x) = I_S2(I_S1(x)), factor = product of the two inversions' factors. */
export const applyMobius3d = (g: Mobius3d, x: Vec3): Mapped | null => invertChain([g.s1, g.s2], x);
/** G⁻¹(x) = I_S1(I_S2(x)). */
export const applyMobius3dInverse = (g: Mobius3d, x: Vec3): Mapped | null => invertChain([g.s2, g.s1], x);

/**
 * One IIS step: inside A → G; else inside B → G⁻¹ (A always tested first); else null (x is in
 * the fundamental domain of this generator, or at a centre).
 */
export function stepMobius3d(g: Mobius3d, x: Vec3): Mapped | null {
  if (inSide(g.a, x)) return applyMobius3d(g, x);
  if (inSide(g.b, x)) return applyMobius3dInverse(g, x);
  return null;
}
