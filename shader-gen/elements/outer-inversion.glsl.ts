/** GLSL twin of outer-inversion.ts. Packing (1 vec4) as inversion: d0 = (c.x, c.y, r, r²). */
import type { OuterInversionElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { invertOffsetGlsl } from './inversion.glsl.ts';

export const outerInversionGlsl: GlslElementTwin<OuterInversionElement> = {
  kind: 'outer-inversion',
  vec4s: 1,
  pack: (e) => [e.c[0], e.c[1], e.r, e.r * e.r],
  step: glslStepBlock(
    `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
float d2 = dx * dx + dy * dy;
if (d2 > d0.w) {
  invertOffset(p, s, d0.xy, d0.z, d0.w, dx, dy, d2);
  continue;
}`,
    [invertOffsetGlsl],
  ),
  inside: glslFunction(
    'outerInversionInside',
    `
bool outerInversionInside(vec2 p, vec4 d0) {
  float dx = p.x - d0.x;
  float dy = p.y - d0.y;
  return dx * dx + dy * dy > d0.w;
}`,
  ),
  boundaryDistance: glslFunction(
    'outerInversionBoundaryDistance',
    `
float outerInversionBoundaryDistance(vec2 p, vec4 d0) {
  return abs(length(p - d0.xy) - d0.z);
}`,
  ),
};
