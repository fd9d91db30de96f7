/**
 * Compound parabolic generator (paper §5.1.2, Figs. 17–18; docs/math-3d.md §6): two facing planes
 * P1 (through q, normal n, kept side n) and P2 (through q + h·n, normal −n) give the translation
 * T = ρ_P2 ∘ ρ_P1 : x ↦ x + 2h·n; the torsion adds the rotation R_θ about the axis through q along n
 * (itself two plane reflections through the axis at angle θ/2). G = R_θ ∘ T, factor 1.
 * R_θ keeps s(x) = (x − q)·n, so the regions are those of T: A = {s < 0} (moved side of P1) → G;
 * B = G(complement of A) = {s > 2h} → G⁻¹; the slab 0 ≤ s ≤ 2h is the fundamental domain.
 */
import { fail, type Mapped, ok, type Result } from './sphere.ts';
import { add3, cross3, dot3, len3, normalize3, scale3, sub3, type Vec3 } from './vec3.ts';

export interface CompoundParabolic3d {
  readonly point: Vec3;
  /** Unit normal of P1, pointing into the slab. */
  readonly normal: Vec3;
  /** Distance between the facing planes; the translation is 2h. */
  readonly gap: number;
  /** Rotation about the axis per application, radians (0: the plain translation of Fig. 17). */
  readonly torsion: number;
}

export function compoundParabolic3d(
  point: Vec3,
  normal: Vec3,
  gap: number,
  torsion: number,
): Result<CompoundParabolic3d> {
  if (!(len3(normal) > 0)) return fail('the plane normal is zero');
  if (!(gap > 0)) return fail('the facing planes must be a positive distance apart');
  if (!Number.isFinite(torsion)) return fail('the torsion angle is not a number');
  return ok({ point, normal: normalize3(normal), gap, torsion });
}

/** Rodrigues: rotation of x about the axis (q, unit n) by θ: v cosθ + (n × v) sinθ + n (n·v)(1 − cosθ), v = x − q. */
export function rotateAboutAxis(q: Vec3, n: Vec3, theta: number, x: Vec3): Vec3 {
  const v = sub3(x, q);
  const c = Math.cos(theta);
  const s = Math.sin(theta);
  return add3(q, add3(add3(scale3(v, c), scale3(cross3(n, v), s)), scale3(n, dot3(n, v) * (1 - c))));
}

/** s(x) = (x − q)·n: < 0 in A, > 2h in B. */
export const slabCoordinate = (g: CompoundParabolic3d, x: Vec3): number => dot3(sub3(x, g.point), g.normal);

/** G(x) = R_θ(x + 2h n). */
export const applyCompoundParabolic3d = (g: CompoundParabolic3d, x: Vec3): Mapped => ({
  x: rotateAboutAxis(g.point, g.normal, g.torsion, add3(x, scale3(g.normal, 2 * g.gap))),
  factor: 1,
});

/** G⁻¹(x) = R_−θ(x) − 2h n. */
export const applyCompoundParabolic3dInverse = (g: CompoundParabolic3d, x: Vec3): Mapped => ({
  x: sub3(rotateAboutAxis(g.point, g.normal, -g.torsion, x), scale3(g.normal, 2 * g.gap)),
  factor: 1,
});

/** One IIS step: s < 0 → G; s > 2h → G⁻¹; else null (in the slab). */
export function stepCompoundParabolic3d(g: CompoundParabolic3d, x: Vec3): Mapped | null {
  const s = slabCoordinate(g, x);
  if (s < 0) return applyCompoundParabolic3d(g, x);
  if (s > 2 * g.gap) return applyCompoundParabolic3dInverse(g, x);
  return null;
}
