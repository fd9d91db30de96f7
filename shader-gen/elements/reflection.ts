/** Line reflection (q, unit n): inside (p−q)·n < 0; ρ(p) = p − 2((p−q)·n) n; scale 1. */
import type { ReflectionElement } from '../../nodes/core/scene.ts';
import type { ElementKind, IisState } from './element-kind.ts';

/** Reflects the state's point in the line (q, n) unconditionally; shared by the generator kinds. */
export function reflectState(st: IisState, qx: number, qy: number, nx: number, ny: number): void {
  const h = 2 * ((st.x - qx) * nx + (st.y - qy) * ny);
  st.x -= h * nx;
  st.y -= h * ny;
}

export const reflection: ElementKind<ReflectionElement> = {
  kind: 'reflection',
  step(e, st) {
    if ((st.x - e.q[0]) * e.n[0] + (st.y - e.q[1]) * e.n[1] >= 0) return false;
    reflectState(st, e.q[0], e.q[1], e.n[0], e.n[1]);
    st.depth += 1;
    return true;
  },
  inside: (e, x, y) => (x - e.q[0]) * e.n[0] + (y - e.q[1]) * e.n[1] < 0,
  boundaryDistance: (e, x, y) => Math.abs((x - e.q[0]) * e.n[0] + (y - e.q[1]) * e.n[1]),
};
