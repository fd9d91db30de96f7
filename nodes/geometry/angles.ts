/**
 * cos(π/k) and sin(π/k) for the integer orders of mirrors and rotations, exact where the value is a
 * simple rational: Math.cos(Math.PI / 2) is 6.1e-17, not 0, and a residue like that keeps a mirror
 * off its axis (p.y − 6e-17 instead of p.y) and costs the generated shader an operation per pass.
 * k = 0 stands for ∞ (π/∞ = 0).
 */

/** cos(π/k): exact for k = ∞ (1), 1 (−1), 2 (0), 3 (1/2); Math.cos otherwise. */
export function cosPiOver(k: number): number {
  if (k === 0) return 1;
  if (k === 1) return -1;
  if (k === 2) return 0;
  if (k === 3) return 0.5;
  return Math.cos(Math.PI / k);
}

/** sin(π/k): exact for k = ∞ (0), 1 (0), 2 (1), 6 (1/2); Math.sin otherwise. */
export function sinPiOver(k: number): number {
  if (k === 0 || k === 1) return 0;
  if (k === 2) return 1;
  if (k === 6) return 0.5;
  return Math.sin(Math.PI / k);
}
