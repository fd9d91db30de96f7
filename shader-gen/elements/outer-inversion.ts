/**
 * Outer circle inversion (c, r): the circle mirror that keeps its inside. Inside (the side it acts
 * on) is |p−c| > r; σ(p) = c + r²(p−c)/|p−c|², scale r²/|p−c|² (invertState: the centre is never
 * reached, it lies on the kept side). NaN compares false and falls through, as in the GLSL twin.
 * GLSL packing (1 vec4), as inversion: d0 = (c.x, c.y, r, r²).
 */
import type { OuterInversionElement } from '../../nodes/core/scene.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';
import { invertOffsetGlsl, invertState } from './inversion.ts';

export const outerInversion: ElementRecord<OuterInversionElement> = {
  kind: 'outer-inversion',
  cpu: {
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
  },
  glsl: {
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
  },
};
