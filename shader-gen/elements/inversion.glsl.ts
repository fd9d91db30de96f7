/**
 * GLSL twin of inversion.ts. Packing (1 vec4): d0 = (c.x, c.y, r, r²): r² computed once on the CPU
 * (in float64, then rounded like every uniform) rather than every pass of the loop.
 */
import type { InversionElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { CENTRE_GUARD } from './inversion.ts';

/**
 * invertState(p, s, c, r, r²): p ← c + k(p−c), s ← s·k with k = min(r²/|p−c|², G²), the centre
 * itself to c + (r·G, 0) (same operations, same order as inversion.ts; r²/0 is +∞ in IEEE
 * arithmetic and min(+∞, G²) = G²). No branch: see inversion.ts CENTRE_GUARD.
 */
export const invertStateGlsl = glslFunction(
  'invertState',
  `
void invertState(inout vec2 p, inout float s, vec2 c, float r, float r2) {
  float dx = p.x - c.x;
  float dy = p.y - c.y;
  float d2 = dx * dx + dy * dy;
  float k = min(r2 / d2, ${floatLiteral(CENTRE_GUARD * CENTRE_GUARD)});
  p = vec2(d2 == 0.0 ? c.x + r * ${floatLiteral(CENTRE_GUARD)} : c.x + dx * k, c.y + dy * k);
  s *= k;
}`,
);

export const inversionGlsl: GlslElementTwin<InversionElement> = {
  kind: 'inversion',
  vec4s: 1,
  pack: (e) => [e.c[0], e.c[1], e.r, e.r * e.r],
  step: glslStepBlock(
    `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
if (!(dx * dx + dy * dy >= d0.w)) {
  invertState(p, s, d0.xy, d0.z, d0.w);
  depth += 1;
  continue;
}`,
    [invertStateGlsl],
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
