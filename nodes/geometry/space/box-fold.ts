/**
 * Box fold (docs/math-3d.md "§10 Box fold and the pseudo-Kleinian"): an axis-aligned box (centre c,
 * half sizes h > 0). Its region is the open outside of the box; the fold brings a point into the
 * closed box by reflecting it in the box's faces, the planes u_k = ±h_k (u = x − c).
 *
 * Per axis the reflections in u = h and u = −h generate the infinite dihedral group, whose
 * fundamental domain is [−h, h] (period 4h). Reflecting until the coordinate is in [−h, h] — the
 * artists' fold u ← 2·clamp(u, −h, h) − u repeated — is one group element, the triangle wave
 *   w = (u + h) − 4h·⌊(u + h)/4h⌋ ∈ [0, 4h),  u' = w − h (w ≤ 2h)  or  3h − w (w > 2h),
 * i.e. u' = σu + τ with σ = +1, τ = −4hk or σ = −1, τ = 2h + 4hk (k = ⌊(u + h)/4h⌋).
 * The three axes fold independently (the faces are orthogonal): an isometry, factor 1.
 */
import type { Mapped } from './sphere.ts';
import type { Vec3 } from './vec3.ts';

export interface BoxFold {
  readonly center: Vec3;
  /** Half sizes along x, y, z, each > 0. */
  readonly halfSize: Vec3;
}

/** One axis's fold t ↦ sign·t + shift (t relative to the centre) for the coordinate u. */
export interface AxisFold {
  readonly sign: 1 | -1;
  readonly shift: number;
}

/** The fold of coordinate u (relative to the centre) into [−h, h]: the triangle wave above. */
export function axisFold(u: number, h: number): AxisFold {
  const period = 4 * h;
  const k = Math.floor((u + h) / period);
  const w = u + h - k * period;
  return w >= 2 * h ? { sign: -1, shift: 2 * h + k * period } : { sign: 1, shift: -k * period };
}

/** Whether x lies in the fold's region, the open outside of the box (some |x_k − c_k| > h_k). */
export function outsideBox(b: BoxFold, x: Vec3): boolean {
  return x.some((v, k) => Math.abs(v - b.center[k]!) > b.halfSize[k]!);
}

/** Distance from a point to the region (0 outside the box): min over axes of h_k − |x_k − c_k|. */
export function boxFoldRegionDistance(b: BoxFold, x: Vec3): number {
  return Math.max(0, Math.min(...x.map((v, k) => b.halfSize[k]! - Math.abs(v - b.center[k]!))));
}

/** The fold of x by the isometry chosen at `at` (the walk moves its pole by the point's map). */
export function applyBoxFold(b: BoxFold, at: Vec3, x: Vec3): Vec3 {
  return x.map((v, k) => {
    const c = b.center[k]!;
    const f = axisFold(at[k]! - c, b.halfSize[k]!);
    return c + f.sign * (v - c) + f.shift;
  }) as unknown as Vec3;
}

/** One IIS step: outside the box → folded into it (factor 1); inside the closed box → null. */
export function stepBoxFold(b: BoxFold, x: Vec3): Mapped | null {
  return outsideBox(b, x) ? { x: applyBoxFold(b, x, x), factor: 1 } : null;
}
