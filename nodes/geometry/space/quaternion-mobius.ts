/**
 * Möbius transformations of R̂³ = R³ ∪ {∞} as 2×2 quaternion matrices (Ahlfors–Clifford matrices,
 * Sakugawa's Sp^K(1,1); docs/math-3d.md "Quaternion Kleinian groups"). M = [[a, b], [c, d]] acts by
 *   x ↦ (a x + b)(c x + d)⁻¹
 * on points x = x₁ + x₂i + x₃j. It maps R̂³ to itself and is invertible when
 *   a b*, c d*, c* a, d* b have no k part   and   a d* − b c* = 1   (q* negates k),
 * and then M⁻¹ = [[d*, −b*], [−c*, a*]]. Points are kept homogeneous, (u, v) ↦ u v⁻¹, so that ∞ = (1, 0)
 * and words of the group act by plain matrix products: M(u, v) = (a u + b v, c u + d v).
 */
import {
  Q_ONE,
  Q_ZERO,
  type Quaternion,
  qAdd,
  qFromPoint,
  qInv,
  qMul,
  qNorm,
  qNorm2,
  qScale,
  qStar,
  qSub,
  qToPoint,
} from './quaternion.ts';
import type { Vec3 } from './vec3.ts';

export interface QMatrix {
  readonly a: Quaternion;
  readonly b: Quaternion;
  readonly c: Quaternion;
  readonly d: Quaternion;
}

/** A point of R̂³ in homogeneous quaternion coordinates: the point u v⁻¹ (∞ when v = 0). */
export type QPoint = readonly [Quaternion, Quaternion];

export const Q_IDENTITY: QMatrix = { a: Q_ONE, b: Q_ZERO, c: Q_ZERO, d: Q_ONE };

/** M N = [[a a' + b c', a b' + b d'], [c a' + d c', c b' + d d']]. */
export function qmMul(m: QMatrix, n: QMatrix): QMatrix {
  return {
    a: qAdd(qMul(m.a, n.a), qMul(m.b, n.c)),
    b: qAdd(qMul(m.a, n.b), qMul(m.b, n.d)),
    c: qAdd(qMul(m.c, n.a), qMul(m.d, n.c)),
    d: qAdd(qMul(m.c, n.b), qMul(m.d, n.d)),
  };
}

/** The pseudo-determinant Δ = a d* − b c* (1 for an Sp^K(1,1) matrix). */
export const pseudoDeterminant = (m: QMatrix): Quaternion =>
  qSub(qMul(m.a, qStar(m.d)), qMul(m.b, qStar(m.c)));

/** M⁻¹ = [[d*, −b*], [−c*, a*]] (valid when Δ = 1). */
export function qmInverse(m: QMatrix): QMatrix {
  return { a: qStar(m.d), b: qScale(qStar(m.b), -1), c: qScale(qStar(m.c), -1), d: qStar(m.a) };
}

/** The largest entry norm (for relative tolerances and for rescaling long products). */
export const qmSize = (m: QMatrix): number => Math.max(qNorm(m.a), qNorm(m.b), qNorm(m.c), qNorm(m.d));

/** A real multiple s·M acts like M (real numbers commute with quaternions). */
export const qmScale = (m: QMatrix, s: number): QMatrix => ({
  a: qScale(m.a, s),
  b: qScale(m.b, s),
  c: qScale(m.c, s),
  d: qScale(m.d, s),
});

export type SpProblem =
  | { readonly kind: 'singular'; readonly detail: string }
  | { readonly kind: 'not-sp'; readonly detail: string };

/**
 * Why M is not (a real multiple of) an Sp^K(1,1) matrix, or null. Δ must be a positive real
 * (then M/√Δ has Δ = 1) and the four products a b*, c d*, c* a, d* b must lie in R³ (no k).
 */
export function spProblem(m: QMatrix, tolerance = 1e-9): SpProblem | null {
  const size2 = qmSize(m) ** 2;
  if (!(size2 > 0) || !Number.isFinite(size2))
    return { kind: 'singular', detail: 'its entries are all zero or not finite' };
  const delta = pseudoDeterminant(m);
  const tol = tolerance * size2;
  if (Math.hypot(delta[1], delta[2], delta[3]) > tol || !(delta[0] > tol))
    return {
      kind: delta[0] > tol || Math.hypot(delta[1], delta[2], delta[3]) > tol ? 'not-sp' : 'singular',
      detail: `its pseudo-determinant a d* − b c* is ${delta.map((v) => Number(v.toFixed(4))).join(' + ')} (i, j, k), not a positive real number`,
    };
  const checks: [string, Quaternion][] = [
    ['a b*', qMul(m.a, qStar(m.b))],
    ['c d*', qMul(m.c, qStar(m.d))],
    ['c* a', qMul(qStar(m.c), m.a)],
    ['d* b', qMul(qStar(m.d), m.b)],
  ];
  for (const [name, q] of checks)
    if (Math.abs(q[3]) > tol)
      return {
        kind: 'not-sp',
        detail: `${name} has a k part ${Number(q[3].toFixed(4))}: M would not map space to itself`,
      };
  return null;
}

/** M scaled to pseudo-determinant 1 (assumes spProblem(M) is null). */
export const spNormalised = (m: QMatrix): QMatrix => qmScale(m, 1 / Math.sqrt(pseudoDeterminant(m)[0]));

/** M (u, v) = (a u + b v, c u + d v). */
export function qmApply(m: QMatrix, p: QPoint): QPoint {
  const [u, v] = p;
  return [qAdd(qMul(m.a, u), qMul(m.b, v)), qAdd(qMul(m.c, u), qMul(m.d, v))];
}

export const pointToQ = (x: Vec3): QPoint => [qFromPoint(x), Q_ONE];

/**
 * The point u v⁻¹ of R³, or null when it is ∞ or farther than `far` (|u| > far·|v|).
 */
export function qPointToSpace(p: QPoint, far = 1e9): Vec3 | null {
  const [u, v] = p;
  if (!(qNorm2(u) < far * far * qNorm2(v))) return null;
  const vi = qInv(v);
  return vi ? qToPoint(qMul(u, vi)) : null;
}

/** (a x + b)(c x + d)⁻¹ for a point x of space (null: x maps to ∞). */
export const mobiusQ = (m: QMatrix, x: Vec3): Vec3 | null => qPointToSpace(qmApply(m, pointToQ(x)));

/** A start point unlikely to be a repelling fixed point of any generator a user types. */
const GENERIC_START: QPoint = [[0.3137, -0.2718, 0.1414, 0], Q_ONE];
/** Squarings: M^(2^60) sends a generic point within ~2⁻⁶⁰ of a parabolic fixed point. */
const SQUARINGS = 60;

/**
 * The attracting fixed point of M (loxodromic), or its fixed point (parabolic), homogeneous:
 * lim M^N(x₀) for a generic x₀, computed as M^(2^n)(x₀) by repeated squaring (rescaled each time,
 * which does not change the map). For an elliptic M the limit need not exist: a point is returned
 * all the same (check it with `fixedPointError`).
 */
export function attractingFixedPoint(m: QMatrix): QPoint {
  let p = m;
  for (let n = 0; n < SQUARINGS; n++) {
    const sq = qmMul(p, p);
    const s = qmSize(sq);
    if (!(s > 0) || !Number.isFinite(s)) break;
    p = qmScale(sq, 1 / s);
  }
  const [u, v] = qmApply(p, GENERIC_START);
  const s = Math.sqrt(qNorm2(u) + qNorm2(v));
  return s > 0 ? [qScale(u, 1 / s), qScale(v, 1 / s)] : GENERIC_START;
}

/**
 * Sakugawa's two-generator family with a parabolic commutator (after soma-arc's
 * 4DKleinCompoundParabolic; docs/math-3d.md): with q_A = cos θ_A + k sin θ_A, q_B = cos θ_B + k sin θ_B,
 *   A = [[q_A, 0], [z q_A, q_A]],   B = [[q_B, q_B], [0, q_B]],
 *   z = x + R j,  R = √(−x (x + 4)) · |sin(θ_A + θ_B)|,  −4 < x < 0.
 * B is the screw motion x ↦ q_B (x + 1) q_B⁻¹ (a turn by 2θ_B about the first axis after a unit
 * step along it); A is conjugate by x ↦ x⁻¹ to the motion y ↦ z + q_A y q_A⁻¹ (1/(A·x) = z + q_A x⁻¹ q_A⁻¹).
 */
export function sakugawaGenerators(x: number, thetaA: number, thetaB: number): readonly [QMatrix, QMatrix] {
  const R = Math.sqrt(-x * (x + 4)) * Math.abs(Math.sin(thetaA + thetaB));
  const z: Quaternion = [x, 0, R, 0];
  const qa: Quaternion = [Math.cos(thetaA), 0, 0, Math.sin(thetaA)];
  const qb: Quaternion = [Math.cos(thetaB), 0, 0, Math.sin(thetaB)];
  return [
    { a: qa, b: Q_ZERO, c: qMul(z, qa), d: qa },
    { a: qb, b: qb, c: Q_ZERO, d: qb },
  ];
}
