/**
 * GLSL twin of inversion.ts. Packing (1 vec4): d0 = (c.x, c.y, r, 0).
 */
import type { InversionElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { CENTRE_GUARD } from './inversion.ts';

/**
 * invertState: p ← c + r²(p−c)/|p−c|², s ← s·r²/|p−c|² (same operations, same order); the
 * centre itself goes to c + (r·G, 0) with scale G² (inversion.ts CENTRE_GUARD).
 */
export const invertStateGlsl = glslFunction(
  'invertState',
  `
void invertState(inout vec2 p, inout float s, vec2 c, float r) {
  float dx = p.x - c.x;
  float dy = p.y - c.y;
  float d2 = dx * dx + dy * dy;
  if (d2 == 0.0) {
    p = vec2(c.x + r * ${floatLiteral(CENTRE_GUARD)}, c.y);
    s *= ${floatLiteral(CENTRE_GUARD * CENTRE_GUARD)};
    return;
  }
  float k = (r * r) / d2;
  p = vec2(c.x + dx * k, c.y + dy * k);
  s *= k;
}`,
);

export const inversionGlsl: GlslElementTwin<InversionElement> = {
  kind: 'inversion',
  vec4s: 1,
  pack: (e) => [e.c[0], e.c[1], e.r, 0],
  step: glslStepBlock(
    `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
if (!(dx * dx + dy * dy >= d0.z * d0.z)) {
  invertState(p, s, d0.xy, d0.z);
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
  return dx * dx + dy * dy < d0.z * d0.z;
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
