/**
 * Outer circle inversion (c, r): the circle mirror that keeps its inside. Inside (the side it acts
 * on) is |p−c| > r; σ(p) = c + r²(p−c)/|p−c|², scale r²/|p−c|² (invertState: the centre is never
 * reached, it lies on the kept side). NaN compares false and falls through, as in the GLSL twin.
 */
import type { OuterInversionElement } from '../../nodes/core/scene.ts';
import type { ElementKind } from './element-kind.ts';
import { invertState } from './inversion.ts';

export const outerInversion: ElementKind<OuterInversionElement> = {
  kind: 'outer-inversion',
  step(e, st) {
    const dx = st.x - e.c[0];
    const dy = st.y - e.c[1];
    if (!(dx * dx + dy * dy > e.r * e.r)) return false;
    invertState(st, e.c[0], e.c[1], e.r);
    st.depth += 1;
    return true;
  },
  inside: (e, x, y) => (x - e.c[0]) ** 2 + (y - e.c[1]) ** 2 > e.r * e.r,
  boundaryDistance: (e, x, y) => Math.abs(Math.hypot(x - e.c[0], y - e.c[1]) - e.r),
};
