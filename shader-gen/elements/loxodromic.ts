/**
 * Loxodromic generator (docs/math.md): inside A, p ← σ_C2(σ_C1(σ_C3(ρ_L(p)))) (ρ_L first); else inside
 * B, p ← ρ_L(σ_C3(σ_C1(σ_C2(p)))) (σ_C2 first). +1 per application.
 */
import type { LoxodromicElement } from '../../nodes/core/scene.ts';
import { inRegion, regionBoundaryDistance } from './disk-region.ts';
import type { ElementKind } from './element-kind.ts';
import { invertState } from './inversion.ts';
import { reflectState } from './reflection.ts';

export const loxodromic: ElementKind<LoxodromicElement> = {
  kind: 'loxodromic',
  step(e, st) {
    const { c1, c2, c3, lq, ln } = e;
    if (inRegion(e.a, st.x, st.y)) {
      reflectState(st, lq[0], lq[1], ln[0], ln[1]);
      invertState(st, c3.c[0], c3.c[1], c3.r);
      invertState(st, c1.c[0], c1.c[1], c1.r);
      invertState(st, c2.c[0], c2.c[1], c2.r);
    } else if (inRegion(e.b, st.x, st.y)) {
      invertState(st, c2.c[0], c2.c[1], c2.r);
      invertState(st, c1.c[0], c1.c[1], c1.r);
      invertState(st, c3.c[0], c3.c[1], c3.r);
      reflectState(st, lq[0], lq[1], ln[0], ln[1]);
    } else return false;
    st.depth += 1;
    return true;
  },
  inside: (e, x, y) => inRegion(e.a, x, y) || inRegion(e.b, x, y),
  boundaryDistance: (e, x, y) =>
    Math.min(regionBoundaryDistance(e.a, x, y), regionBoundaryDistance(e.b, x, y)),
};
