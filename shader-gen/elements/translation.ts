/**
 * Translation strip (closed form, math.md): h = (p − q)·n, k = ⌊h/D⌋; tile 0 ≤ h < D; otherwise
 * p ← p − kD·n in one go, depth += |k| (the number of single translations by ±D·n it stands for).
 * Scale 1 (an isometry).
 */
import type { TranslationElement } from '../../nodes/core/scene.ts';
import type { ElementKind } from './element-kind.ts';
import { stripBoundaryDistance, stripIndex } from './strip-fold.ts';

export const translation: ElementKind<TranslationElement> = {
  kind: 'translation',
  step(e, st) {
    const k = stripIndex(e, st.x, st.y);
    if (k === 0) return false;
    st.x -= k * e.period * e.n[0];
    st.y -= k * e.period * e.n[1];
    st.depth += Math.abs(k);
    return true;
  },
  inside: (e, x, y) => stripIndex(e, x, y) !== 0,
  boundaryDistance: stripBoundaryDistance,
};
