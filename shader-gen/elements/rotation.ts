/**
 * Rotation of order k about c (closed form, docs/math.md): θ = 2π/k, the tile is the wedge from the
 * unit direction b1 counter-clockwise by θ. With arg ∈ [0, 2π) measured from b1 and
 * m = ⌊arg/θ⌋ (at most k − 1), rotate by −mθ about c; depth += m (the single steps "rotate by −θ"
 * it stands for). The centre itself is in the tile (arg taken as 0). Scale 1.
 */
import type { RotationElement } from '../../nodes/core/scene.ts';
import type { ElementKind } from './element-kind.ts';

/** m = ⌊arg/θ⌋ ∈ [0, k − 1] for the point (dx, dy) relative to the centre. */
export function wedgeIndex(e: RotationElement, dx: number, dy: number): number {
  const [ux, uy] = e.b1;
  let arg = Math.atan2(ux * dy - uy * dx, ux * dx + uy * dy);
  if (arg < 0) arg += 2 * Math.PI;
  return Math.min(e.order - 1, Math.floor((arg * e.order) / (2 * Math.PI)));
}

/** Distance from (dx, dy) (relative to the ray's origin) to the ray in unit direction (ux, uy). */
function rayDistance(dx: number, dy: number, ux: number, uy: number): number {
  const t = dx * ux + dy * uy;
  return t <= 0 ? Math.hypot(dx, dy) : Math.abs(ux * dy - uy * dx);
}

export const rotation: ElementKind<RotationElement> = {
  kind: 'rotation',
  step(e, st) {
    const dx = st.x - e.c[0];
    const dy = st.y - e.c[1];
    const m = wedgeIndex(e, dx, dy);
    if (m <= 0) return false;
    const t = (-2 * Math.PI * m) / e.order;
    const cos = Math.cos(t);
    const sin = Math.sin(t);
    st.x = e.c[0] + cos * dx - sin * dy;
    st.y = e.c[1] + sin * dx + cos * dy;
    st.depth += m;
    return true;
  },
  inside: (e, x, y) => wedgeIndex(e, x - e.c[0], y - e.c[1]) > 0,
  boundaryDistance(e, x, y) {
    const dx = x - e.c[0];
    const dy = y - e.c[1];
    const t = (2 * Math.PI) / e.order;
    const [ux, uy] = e.b1;
    const vx = Math.cos(t) * ux - Math.sin(t) * uy;
    const vy = Math.sin(t) * ux + Math.cos(t) * uy;
    return Math.min(rayDistance(dx, dy, ux, uy), rayDistance(dx, dy, vx, vy));
  },
};
