/**
 * Compound loxodromic generator (paper §5.1.2, Fig. 20; docs/math-3d.md §3): the two-sphere map
 * H = I_S2 ∘ I_S1 followed by the rotation R = I_S4 ∘ I_S3, with S3 = Sphere(P, P', P'', Q1),
 * S4 = Sphere(P, P', P'', Q2). S3 and S4 are orthogonal to S1 and S2, so R commutes with H and
 * keeps each side of S1 and S1': G = R ∘ H has the same regions A, B as H. The paper prints
 * (I_S4∘I_S3)∘(I_S1∘I_S2) for "inside S1", which applies H⁻¹ there; the derived map is
 * inside A: G = (I_S4∘I_S3)∘(I_S2∘I_S1); inside B: G⁻¹ = (I_S1∘I_S2)∘(I_S3∘I_S4).
 */
import { inSide, invertChain, type Mobius3d, mobius3d } from './mobius-3d.ts';
import { fail, type Mapped, ok, type Result, type Sphere, sphereThroughInverses } from './sphere.ts';
import type { Vec3 } from './vec3.ts';

export interface CompoundLoxodromic3d {
  readonly base: Mobius3d;
  readonly s3: Sphere;
  readonly s4: Sphere;
}

/** Builds S3, S4 from the control points; fails with the failing construction's message. */
export function compoundLoxodromic3d(
  s1: Sphere,
  s2: Sphere,
  p: Vec3,
  q1: Vec3,
  q2: Vec3,
): Result<CompoundLoxodromic3d> {
  const base = mobius3d(s1, s2);
  if (!base.ok) return base;
  const s3 = sphereThroughInverses(s1, s2, p, q1);
  if (!s3.ok) return fail(`S3: ${s3.error}`);
  const s4 = sphereThroughInverses(s1, s2, p, q2);
  if (!s4.ok) return fail(`S4: ${s4.error}`);
  return ok({ base: base.value, s3: s3.value, s4: s4.value });
}

/** G(x) = I_S4(I_S3(I_S2(I_S1(x)))) — I_S1 first. */
export const applyCompoundLoxodromic3d = (g: CompoundLoxodromic3d, x: Vec3): Mapped | null =>
  invertChain([g.base.s1, g.base.s2, g.s3, g.s4], x);

/** G⁻¹(x) = I_S1(I_S2(I_S3(I_S4(x)))) — I_S4 first. */
export const applyCompoundLoxodromic3dInverse = (g: CompoundLoxodromic3d, x: Vec3): Mapped | null =>
  invertChain([g.s4, g.s3, g.base.s2, g.base.s1], x);

/** One IIS step: inside A → G; else inside B → G⁻¹; else null. */
export function stepCompoundLoxodromic3d(g: CompoundLoxodromic3d, x: Vec3): Mapped | null {
  if (inSide(g.base.a, x)) return applyCompoundLoxodromic3d(g, x);
  if (inSide(g.base.b, x)) return applyCompoundLoxodromic3dInverse(g, x);
  return null;
}
