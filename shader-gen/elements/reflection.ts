/**
 * Line reflection (q, unit n): inside (p−q)·n < 0; ρ(p) = p − 2((p−q)·n) n; scale 1.
 * GLSL packing (1 vec4): d0 = (q.x, q.y, n.x, n.y), n a unit normal. The
 * step reuses the side test's (p−q)·n for the reflection (reflectState's operations, computed
 * once: the same value the test saw).
 */
import type { ReflectionElement } from '../../nodes/core/scene.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { type ElementRecord, glslStepBlock, type IisState } from './element-kind.ts';

/** Reflects the state's point in the line (q, n) unconditionally; shared by the generator kinds. */
export function reflectState(st: IisState, qx: number, qy: number, nx: number, ny: number): void {
  const h = 2 * ((st.x - qx) * nx + (st.y - qy) * ny);
  st.x -= h * nx;
  st.y -= h * ny;
}

/** reflectState: h = 2((p−q)·n), p ← p − h n (same operations, same order). */
export const reflectStateGlsl = glslFunction(
  'reflectState',
  `
void reflectState(inout vec2 p, vec2 q, vec2 n) {
  float h = 2.0 * ((p.x - q.x) * n.x + (p.y - q.y) * n.y);
  p = vec2(p.x - h * n.x, p.y - h * n.y);
}`,
);

export const reflection: ElementRecord<ReflectionElement> = {
  kind: 'reflection',
  cpu: {
    step(e, st) {
      if ((st.x - e.q[0]) * e.n[0] + (st.y - e.q[1]) * e.n[1] >= 0) return false;
      reflectState(st, e.q[0], e.q[1], e.n[0], e.n[1]);
      st.depth += 1;
      return true;
    },
    inside: (e, x, y) => (x - e.q[0]) * e.n[0] + (y - e.q[1]) * e.n[1] < 0,
    boundaryDistance: (e, x, y) => Math.abs((x - e.q[0]) * e.n[0] + (y - e.q[1]) * e.n[1]),
  },
  glsl: {
    vec4s: 1,
    pack: (e) => [e.q[0], e.q[1], e.n[0], e.n[1]],
    step: glslStepBlock(`
float h = (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
if (!(h >= 0.0)) {
  h *= 2.0;
  p = vec2(p.x - h * d0.z, p.y - h * d0.w);
  continue;
}`),
    inside: glslFunction(
      'reflectionInside',
      `
bool reflectionInside(vec2 p, vec4 d0) {
  return (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w < 0.0;
}`,
    ),
    boundaryDistance: glslFunction(
      'reflectionBoundaryDistance',
      `
float reflectionBoundaryDistance(vec2 p, vec4 d0) {
  return abs((p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w);
}`,
    ),
  },
};
