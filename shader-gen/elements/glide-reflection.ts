/**
 * Glide reflection along the axis through q in direction n, period D (closed form, docs/math.md): the
 * glide is "translate by D·n, then reflect in the axis". With k = ⌊h/D⌋, h = (p − q)·n: translate
 * by −kD·n into the tile 0 ≤ h < D and, when k is odd, reflect across the axis (normal perp(n)).
 * depth += |k|; scale 1.
 */
import type { GlideReflectionElement } from '../../nodes/core/scene.ts';
import type { ElementKind } from './element-kind.ts';
import { reflectState } from './reflection.ts';
import { stripBoundaryDistance, stripIndex } from './strip-fold.ts';

export const glideReflection: ElementKind<GlideReflectionElement> = {
  kind: 'glide-reflection',
  step(e, st) {
    const k = stripIndex(e, st.x, st.y);
    if (k === 0) return false;
    st.x -= k * e.period * e.n[0];
    st.y -= k * e.period * e.n[1];
    // The axis is the line through q along n: its normal is perp(n) = (−n_y, n_x).
    if (k % 2 !== 0) reflectState(st, e.q[0], e.q[1], -e.n[1], e.n[0]);
    st.depth += Math.abs(k);
    return true;
  },
  inside: (e, x, y) => stripIndex(e, x, y) !== 0,
  boundaryDistance: stripBoundaryDistance,
};
