/**
 * Two-circle Möbius generator: in A, g = σ_C2∘σ_C1 (σ_C1 first); else in B, g⁻¹ = σ_C1∘σ_C2.
 * A is always tested before B (docs/math.md). Scale: the product of both inversions' factors.
 */
import type { MobiusElement } from '../../nodes/core/scene.ts';
import { inRegion, regionBoundaryDistance } from './disk-region.ts';
import type { ElementKind } from './element-kind.ts';
import { invertState } from './inversion.ts';

export const mobius: ElementKind<MobiusElement> = {
  kind: 'mobius',
  step(e, st) {
    const { c1, c2 } = e;
    if (inRegion(e.a, st.x, st.y)) {
      invertState(st, c1.c[0], c1.c[1], c1.r);
      invertState(st, c2.c[0], c2.c[1], c2.r);
    } else if (inRegion(e.b, st.x, st.y)) {
      invertState(st, c2.c[0], c2.c[1], c2.r);
      invertState(st, c1.c[0], c1.c[1], c1.r);
    } else return false;
    st.depth += 1;
    return true;
  },
  inside: (e, x, y) => inRegion(e.a, x, y) || inRegion(e.b, x, y),
  boundaryDistance: (e, x, y) =>
    Math.min(regionBoundaryDistance(e.a, x, y), regionBoundaryDistance(e.b, x, y)),
};
