/**
 * Translation strip (closed form, docs/math.md): h = (p − q)·n, k = ⌊h/D⌋; tile 0 ≤ h < D; otherwise
 * p ← p − k·t in one go with t = D·n (or the element's oblique `shift`, t·n = D), depth += |k|
 * (the number of single translations by ±t it stands for). Scale 1 (an isometry).
 */
import type { TranslationElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import type { ElementKind } from './element-kind.ts';
import { stripBoundaryDistance, stripIndex } from './strip-fold.ts';

/** The translation vector t: the element's `shift`, or period·n. */
export const translationShift = (e: TranslationElement): Vec2 =>
  e.shift ?? [e.period * e.n[0], e.period * e.n[1]];

export const translation: ElementKind<TranslationElement> = {
  kind: 'translation',
  step(e, st) {
    const k = stripIndex(e, st.x, st.y);
    if (k === 0) return false;
    const [tx, ty] = translationShift(e);
    st.x -= k * tx;
    st.y -= k * ty;
    st.depth += Math.abs(k);
    return true;
  },
  inside: (e, x, y) => stripIndex(e, x, y) !== 0,
  boundaryDistance: stripBoundaryDistance,
};
