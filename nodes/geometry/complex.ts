/**
 * Complex numbers as [re, im] pairs (the same shape as a world point: z = x + iy), for Möbius
 * maps given by a matrix. Pure functions; each states its formula.
 */
import type { Vec2 } from '../core/values.ts';

export type Complex = Vec2;

export const complex = (re: number, im = 0): Complex => [re, im];
export const ONE: Complex = [1, 0];
export const ZERO: Complex = [0, 0];

/** (a + ib) + (c + id) = (a + c) + i(b + d). */
export const cadd = (z: Complex, w: Complex): Complex => [z[0] + w[0], z[1] + w[1]];
/** (a + ib) − (c + id) = (a − c) + i(b − d). */
export const csub = (z: Complex, w: Complex): Complex => [z[0] - w[0], z[1] - w[1]];
/** (a + ib)(c + id) = (ac − bd) + i(ad + bc). */
export const cmul = (z: Complex, w: Complex): Complex => [
  z[0] * w[0] - z[1] * w[1],
  z[0] * w[1] + z[1] * w[0],
];
/** k·(a + ib) for real k. */
export const cscale = (z: Complex, k: number): Complex => [z[0] * k, z[1] * k];
/** conj(a + ib) = a − ib. */
export const cconj = (z: Complex): Complex => [z[0], -z[1]];
/** |z|² = a² + b². */
export const cabs2 = (z: Complex): number => z[0] * z[0] + z[1] * z[1];
/** |z| = √(a² + b²) (hypot: no overflow for large parts). */
export const cabs = (z: Complex): number => Math.hypot(z[0], z[1]);
/** −z. */
export const cneg = (z: Complex): Complex => [-z[0], -z[1]];

/** z / w = z·conj(w)/|w|². Division by 0 gives non-finite parts (callers check |w| first). */
export function cdiv(z: Complex, w: Complex): Complex {
  const d = cabs2(w);
  return [(z[0] * w[0] + z[1] * w[1]) / d, (z[1] * w[0] - z[0] * w[1]) / d];
}

/**
 * Principal square root: for z = a + ib with m = |z|, √z = √((m + a)/2) + i·sign(b)·√((m − a)/2)
 * (real part ≥ 0; sign(0) taken as +). Computed in the form that avoids cancellation.
 */
export function csqrt(z: Complex): Complex {
  const [a, b] = z;
  const m = cabs(z);
  if (m === 0) return [0, 0];
  if (a >= 0) {
    const t = Math.sqrt((m + a) / 2);
    return [t, b / (2 * t)];
  }
  const t = Math.sqrt((m - a) / 2);
  return [Math.abs(b) / (2 * t), b < 0 ? -t : t];
}

/** Whether |z − w| ≤ eps·max(1, |z|, |w|). */
export const cnear = (z: Complex, w: Complex, eps = 1e-9): boolean =>
  cabs(csub(z, w)) <= eps * Math.max(1, cabs(z), cabs(w));
