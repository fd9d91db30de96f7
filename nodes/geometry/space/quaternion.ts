/**
 * Quaternions q = w + x·i + y·j + z·k as [w, x, y, z], with i² = j² = k² = ijk = −1
 * (docs/math-3d.md "Quaternion Kleinian groups"). Space R³ is the quaternions with no k part:
 * the point (x, y, z) is x + y·i + z·j, so the Clifford transposition q* (which reverses the
 * product ij = k, i.e. negates k) fixes every point.
 */
import type { Vec3 } from './vec3.ts';

export type Quaternion = readonly [number, number, number, number];

export const Q_ZERO: Quaternion = [0, 0, 0, 0];
export const Q_ONE: Quaternion = [1, 0, 0, 0];

export const qAdd = (p: Quaternion, q: Quaternion): Quaternion => [
  p[0] + q[0],
  p[1] + q[1],
  p[2] + q[2],
  p[3] + q[3],
];
export const qSub = (p: Quaternion, q: Quaternion): Quaternion => [
  p[0] - q[0],
  p[1] - q[1],
  p[2] - q[2],
  p[3] - q[3],
];
export const qScale = (q: Quaternion, s: number): Quaternion => [q[0] * s, q[1] * s, q[2] * s, q[3] * s];

/** Hamilton's product pq (not commutative: ij = k = −ji). */
export const qMul = (p: Quaternion, q: Quaternion): Quaternion => [
  p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
  p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
  p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
  p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
];

/** |q|² = w² + x² + y² + z² (multiplicative: |pq| = |p||q|). */
export const qNorm2 = (q: Quaternion): number => q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
export const qNorm = (q: Quaternion): number => Math.sqrt(qNorm2(q));

/** The conjugate q̄ = w − xi − yj − zk. */
export const qConj = (q: Quaternion): Quaternion => [q[0], -q[1], -q[2], -q[3]];

/** The Clifford transposition q* = w + xi + yj − zk (the reversion of the Clifford algebra of i, j). */
export const qStar = (q: Quaternion): Quaternion => [q[0], q[1], q[2], -q[3]];

/** q⁻¹ = q̄/|q|², or null for 0. */
export function qInv(q: Quaternion): Quaternion | null {
  const n = qNorm2(q);
  return n > 0 ? qScale(qConj(q), 1 / n) : null;
}

/** The point (x, y, z) of space as the quaternion x + yi + zj. */
export const qFromPoint = (p: Vec3): Quaternion => [p[0], p[1], p[2], 0];
/** The quaternion's point of space (its k part, zero for Sp matrices' images, is dropped). */
export const qToPoint = (q: Quaternion): Vec3 => [q[0], q[1], q[2]];
