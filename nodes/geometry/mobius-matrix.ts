/**
 * Möbius maps from a matrix (docs/math.md "Möbius from a matrix"): g(z) = (az + b)/(cz + d), complex
 * a, b, c, d, normalised so that ad − bc = 1. Type from the trace, isometric circles (the Ford-domain
 * IIS rule) and the matrix of a composition of two circle inversions.
 */
import type { Circle } from '../core/values.ts';
import {
  type Complex,
  cabs,
  cabs2,
  cadd,
  cconj,
  cdiv,
  cmul,
  cneg,
  complex,
  cscale,
  csqrt,
  csub,
} from './complex.ts';

export interface MobiusMatrix {
  readonly a: Complex;
  readonly b: Complex;
  readonly c: Complex;
  readonly d: Complex;
}

/** Relative tolerance for det = 0, c = 0 and the type thresholds (trace² = 4, real trace²). */
export const MATRIX_EPS = 1e-9;

/** det = ad − bc. */
export const det = (m: MobiusMatrix): Complex => csub(cmul(m.a, m.d), cmul(m.b, m.c));

/** Largest entry modulus: the scale that "det ≈ 0" and "c ≈ 0" are measured against. */
const size = (m: MobiusMatrix): number => Math.max(cabs(m.a), cabs(m.b), cabs(m.c), cabs(m.d));

/**
 * Divides every entry by s = √(ad − bc) so that the new determinant is (ad − bc)/s² = 1. The map is
 * unchanged (numerator and denominator scale alike). null when |det| ≤ ε·size² (not invertible).
 */
export function normalizeMatrix(m: MobiusMatrix): MobiusMatrix | null {
  const D = det(m);
  const k = size(m);
  if (!(cabs(D) > MATRIX_EPS * k * k)) return null;
  const s = csqrt(D);
  return { a: cdiv(m.a, s), b: cdiv(m.b, s), c: cdiv(m.c, s), d: cdiv(m.d, s) };
}

/** g(z) = (az + b)/(cz + d); null at the pole z = −d/c (g maps it to ∞). */
export function applyMatrix(m: MobiusMatrix, z: Complex): Complex | null {
  const den = cadd(cmul(m.c, z), m.d);
  if (cabs2(den) === 0) return null;
  return cdiv(cadd(cmul(m.a, z), m.b), den);
}

/** Inverse of a det-1 matrix: [[a, b], [c, d]]⁻¹ = [[d, −b], [−c, a]]. */
export const inverseMatrix = (m: MobiusMatrix): MobiusMatrix => ({
  a: m.d,
  b: cneg(m.b),
  c: cneg(m.c),
  d: m.a,
});

/** Matrix product m·n (the map m∘n: n applied first). */
export const composeMatrices = (m: MobiusMatrix, n: MobiusMatrix): MobiusMatrix => ({
  a: cadd(cmul(m.a, n.a), cmul(m.b, n.c)),
  b: cadd(cmul(m.a, n.b), cmul(m.b, n.d)),
  c: cadd(cmul(m.c, n.a), cmul(m.d, n.c)),
  d: cadd(cmul(m.c, n.b), cmul(m.d, n.d)),
});

/** Whether c is (relatively) zero: g is affine and has no isometric circles. */
export const isAffine = (m: MobiusMatrix): boolean => cabs(m.c) <= MATRIX_EPS * size(m);

export type MatrixType = 'elliptic' | 'parabolic' | 'hyperbolic' | 'loxodromic';

export interface MatrixClass {
  readonly type: MatrixType;
  /** τ = a + d of the det-1 matrix (defined up to sign). */
  readonly trace: Complex;
  /** Elliptic: the rotation angle θ about the fixed point, τ = ±2 cos(θ/2). */
  readonly rotation?: number;
  /**
   * Hyperbolic / loxodromic: the multiplier k = λ², λ the root of λ + 1/λ = τ with |λ| ≥ 1: g is
   * conjugate to z ↦ kz (each step scales by |k| and turns by arg k about its fixed points).
   */
  readonly multiplier?: Complex;
}

/**
 * Type from τ² (sign-free): real in [0, 4) → elliptic; = 4 → parabolic; real > 4 → hyperbolic
 * (τ real); otherwise (not real, or negative) → loxodromic.
 */
export function classifyMatrix(m: MobiusMatrix): MatrixClass {
  const trace = cadd(m.a, m.d);
  const t2 = cmul(trace, trace);
  const tol = MATRIX_EPS * Math.max(1, cabs(t2));
  const real = Math.abs(t2[1]) <= tol;
  if (real && Math.abs(t2[0] - 4) <= tol) return { type: 'parabolic', trace };
  if (real && t2[0] >= 0 && t2[0] < 4) {
    return { type: 'elliptic', trace, rotation: 2 * Math.acos(Math.min(1, Math.sqrt(t2[0]) / 2)) };
  }
  // λ = (τ + √(τ² − 4))/2 with the root chosen so that |λ| ≥ 1; k = λ².
  const root = csqrt(csub(t2, complex(4)));
  let lambda = cscale(cadd(trace, root), 0.5);
  if (cabs(lambda) < 1) lambda = cscale(csub(trace, root), 0.5);
  return { type: real && t2[0] > 4 ? 'hyperbolic' : 'loxodromic', trace, multiplier: cmul(lambda, lambda) };
}

/**
 * Isometric circles of a det-1 matrix with c ≠ 0 (where |g'(z)| = 1/|cz + d|² = 1):
 * I(g): centre −d/c, radius 1/|c|; I(g⁻¹): centre a/c, radius 1/|c|. g maps the outside of I(g)
 * onto the inside of I(g⁻¹). They are disjoint or tangent iff |a/c + d/c| = |τ|/|c| ≥ 2/|c|,
 * i.e. |τ| ≥ 2.
 */
export function isometricCircles(m: MobiusMatrix): { readonly forward: Circle; readonly backward: Circle } {
  const r = 1 / cabs(m.c);
  return { forward: { c: cdiv(cneg(m.d), m.c), r }, backward: { c: cdiv(m.a, m.c), r } };
}

/**
 * Inversion in a circle as an anti-Möbius map: σ_C(z) = c + r²/conj(z − c) = M(z̄) with
 * M = [[c, r² − |c|²], [1, −conj c]] (det −r²): (c·z̄ − |c|² + r²)/(z̄ − conj c).
 */
export const inversionMatrix = (circle: Circle): MobiusMatrix => ({
  a: circle.c,
  b: complex(circle.r * circle.r - cabs2(circle.c)),
  c: complex(1),
  d: cneg(cconj(circle.c)),
});

/**
 * The matrix of g = σ_C2∘σ_C1 (a true Möbius map): σ_C2(σ_C1(z)) = M2(conj(M1(z̄))) = M2(M̄1(z)),
 * so g = M2·M̄1 with M̄1 the entrywise conjugate; det = r1² r2², normalised to 1.
 */
export function twoCircleMatrix(c1: Circle, c2: Circle): MobiusMatrix | null {
  const m1 = inversionMatrix(c1);
  const conj1: MobiusMatrix = { a: cconj(m1.a), b: cconj(m1.b), c: cconj(m1.c), d: cconj(m1.d) };
  return normalizeMatrix(composeMatrices(inversionMatrix(c2), conj1));
}
