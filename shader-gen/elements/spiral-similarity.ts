/**
 * Spiral similarity about c (closed form, docs/math.md): the composition of the reflections in the
 * lines through c at angles 0 and φ (a rotation by 2φ) and the inversions in the circles r1 then
 * r2 about c (a scaling by λ = (r2/r1)²): g(p) = c + λ R_2φ (p − c). Tile: the annulus
 * r1 ≤ |p − c| < r1·λ = r2²/r1. With m = ⌊log(|p − c|/r1)/log λ⌋, apply g^(−m) at once:
 * p ← c + λ^(−m) R_(−2mφ) (p − c), scale ×λ^(−m) (the conformal factor of g is λ), depth += |m|.
 * The centre is the fixed point (the limit set): it never reaches the tile.
 */
import type { SpiralSimilarityElement } from '../../nodes/core/scene.ts';
import type { ElementKind } from './element-kind.ts';

/** λ = (r2/r1)², the scaling of one step. */
export function spiralRatio(e: SpiralSimilarityElement): number {
  const t = e.r2 / e.r1;
  return t * t;
}

/** m = ⌊log(ρ/r1)/log λ⌋ for ρ = |p − c| (−∞ at the centre). */
const annulusIndex = (e: SpiralSimilarityElement, rho: number): number =>
  Math.floor(Math.log(rho / e.r1) / Math.log(spiralRatio(e)));

export const spiralSimilarity: ElementKind<SpiralSimilarityElement> = {
  kind: 'spiral-similarity',
  step(e, st) {
    const dx = st.x - e.c[0];
    const dy = st.y - e.c[1];
    const rho = Math.hypot(dx, dy);
    if (rho === 0) {
      st.depth += 1; // the fixed point: one step at a time until maxIterations (not escaped)
      return true;
    }
    const m = annulusIndex(e, rho);
    if (m === 0) return false;
    const k = spiralRatio(e) ** -m;
    const t = -2 * m * e.angle;
    const cos = Math.cos(t) * k;
    const sin = Math.sin(t) * k;
    st.x = e.c[0] + cos * dx - sin * dy;
    st.y = e.c[1] + sin * dx + cos * dy;
    st.s *= k;
    st.depth += Math.abs(m);
    return true;
  },
  inside: (e, x, y) => annulusIndex(e, Math.hypot(x - e.c[0], y - e.c[1])) !== 0,
  boundaryDistance(e, x, y) {
    const rho = Math.hypot(x - e.c[0], y - e.c[1]);
    return Math.min(Math.abs(rho - e.r1), Math.abs(rho - e.r1 * spiralRatio(e)));
  },
};
