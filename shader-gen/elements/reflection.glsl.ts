/**
 * GLSL twin of reflection.ts. Packing (1 vec4): d0 = (q.x, q.y, n.x, n.y), n a unit normal. The
 * step reuses the side test's (p−q)·n for the reflection (reflectState's operations, computed
 * once: the same value the test saw).
 */
import type { ReflectionElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';

/** reflectState: h = 2((p−q)·n), p ← p − h n (same operations, same order). */
export const reflectStateGlsl = glslFunction(
  'reflectState',
  `
void reflectState(inout vec2 p, vec2 q, vec2 n) {
  float h = 2.0 * ((p.x - q.x) * n.x + (p.y - q.y) * n.y);
  p = vec2(p.x - h * n.x, p.y - h * n.y);
}`,
);

export const reflectionGlsl: GlslElementTwin<ReflectionElement> = {
  kind: 'reflection',
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
};
