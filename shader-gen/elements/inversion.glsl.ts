/**
 * GLSL twin of inversion.ts. Packing (1 vec4): d0 = (c.x, c.y, r, r²): r² computed once on the CPU
 * (in float64, then rounded like every uniform) rather than every pass of the loop.
 */
import type { InversionElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { CENTRE_GUARD, CENTRE_SHIFT } from './inversion.ts';

/**
 * invertOffset(p, s, c, r, r², dx, dy, d²) with (dx, dy) = p − c and d² = dx² + dy² already at
 * hand (the inversion's own side test computed them): k = min(r²/d², G²), p ← c + (dx + r/G, dy)·k,
 * s ← s·k (same operations, same order as inversion.ts; r²/0 is +∞ in IEEE arithmetic and
 * min(+∞, G²) = G², so the centre goes to c + (r·G, 0)). No branch and no `?:`: see inversion.ts
 * CENTRE_GUARD.
 */
export const invertOffsetGlsl = glslFunction(
  'invertOffset',
  `
void invertOffset(inout vec2 p, inout float s, vec2 c, float r, float r2, float dx, float dy, float d2) {
  float k = min(r2 / d2, ${floatLiteral(CENTRE_GUARD * CENTRE_GUARD)});
  p = vec2(c.x + (dx + r * ${floatLiteral(CENTRE_SHIFT)}) * k, c.y + dy * k);
  s *= k;
}`,
);

/** invertState(p, s, c, r, r²): inversion.ts invertState, for the kinds that invert unconditionally. */
export const invertStateGlsl = glslFunction(
  'invertState',
  `
void invertState(inout vec2 p, inout float s, vec2 c, float r, float r2) {
  float dx = p.x - c.x;
  float dy = p.y - c.y;
  invertOffset(p, s, c, r, r2, dx, dy, dx * dx + dy * dy);
}`,
  [invertOffsetGlsl],
);

export const inversionGlsl: GlslElementTwin<InversionElement> = {
  kind: 'inversion',
  vec4s: 1,
  pack: (e) => [e.c[0], e.c[1], e.r, e.r * e.r],
  step: glslStepBlock(
    `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
float d2 = dx * dx + dy * dy;
if (!(d2 >= d0.w)) {
  invertOffset(p, s, d0.xy, d0.z, d0.w, dx, dy, d2);
  continue;
}`,
    [invertOffsetGlsl],
  ),
  inside: glslFunction(
    'inversionInside',
    `
bool inversionInside(vec2 p, vec4 d0) {
  float dx = p.x - d0.x;
  float dy = p.y - d0.y;
  return dx * dx + dy * dy < d0.w;
}`,
  ),
  boundaryDistance: glslFunction(
    'inversionBoundaryDistance',
    `
float inversionBoundaryDistance(vec2 p, vec4 d0) {
  return abs(length(p - d0.xy) - d0.z);
}`,
  ),
};
