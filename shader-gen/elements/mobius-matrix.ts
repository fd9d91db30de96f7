/**
 * Möbius map from a det-1 matrix, Ford-domain rule (docs/math.md "Möbius from a matrix"): inside the
 * isometric circle I(g) (centre −d/c) apply g(z) = (az + b)/(cz + d), scale 1/|cz + d|²; else inside
 * I(g⁻¹) (centre a/c) apply g⁻¹(z) = (dz − b)/(−cz + a), scale 1/|−cz + a|². I(g) is tested first.
 */
import type { MobiusMatrixElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import { inRegion, regionBoundaryDistance } from './disk-region.ts';
import type { ElementKind, IisState } from './element-kind.ts';

/**
 * z ← (p z + q)/(r z + t) for complex p, q, r, t, s *= 1/|r z + t|²: the quotient written out in
 * reals, num·conj(den)/|den|².
 */
function applyMobius(st: IisState, p: Vec2, q: Vec2, r: Vec2, t: Vec2, sign: number): void {
  const { x, y } = st;
  const nx = p[0] * x - p[1] * y + sign * q[0];
  const ny = p[0] * y + p[1] * x + sign * q[1];
  const dx = sign * (r[0] * x - r[1] * y) + t[0];
  const dy = sign * (r[0] * y + r[1] * x) + t[1];
  const d2 = dx * dx + dy * dy;
  st.x = (nx * dx + ny * dy) / d2;
  st.y = (ny * dx - nx * dy) / d2;
  st.s /= d2;
}

export const mobiusMatrix: ElementKind<MobiusMatrixElement> = {
  kind: 'mobius-matrix',
  step(e, st) {
    if (inRegion(e.forward, st.x, st.y)) applyMobius(st, e.a, e.b, e.c, e.d, 1);
    else if (inRegion(e.backward, st.x, st.y)) applyMobius(st, e.d, e.b, e.c, e.a, -1);
    else return false;
    st.depth += 1;
    return true;
  },
  inside: (e, x, y) => inRegion(e.forward, x, y) || inRegion(e.backward, x, y),
  boundaryDistance: (e, x, y) =>
    Math.min(regionBoundaryDistance(e.forward, x, y), regionBoundaryDistance(e.backward, x, y)),
};
