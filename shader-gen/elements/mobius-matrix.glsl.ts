/**
 * GLSL twin of mobius-matrix.ts. Packing (4 vec4): d0 = (a.re, a.im, b.re, b.im),
 * d1 = (c.re, c.im, d.re, d.im), d2 = region I(g) (forward), d3 = region I(g⁻¹) (backward).
 */
import type { MobiusMatrixElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { inRegionGlsl, packRegion, regionBoundaryDistanceGlsl } from './disk-region.glsl.ts';

/** z ← (P z + sgn Q)/(sgn R z + T), s ← s/|sgn R z + T|², written out in reals as on the CPU. */
export const applyMobiusGlsl = glslFunction(
  'applyMobius',
  `
void applyMobius(inout vec2 z, inout float s, vec2 P, vec2 Q, vec2 R, vec2 T, float sgn) {
  float x = z.x;
  float y = z.y;
  float nx = P.x * x - P.y * y + sgn * Q.x;
  float ny = P.x * y + P.y * x + sgn * Q.y;
  float dx = sgn * (R.x * x - R.y * y) + T.x;
  float dy = sgn * (R.x * y + R.y * x) + T.y;
  float d2 = dx * dx + dy * dy;
  z = vec2((nx * dx + ny * dy) / d2, (ny * dx - nx * dy) / d2);
  s /= d2;
}`,
);

const ARGS = 'vec4 d0, vec4 d1, vec4 d2, vec4 d3';

export const mobiusMatrixGlsl: GlslElementTwin<MobiusMatrixElement> = {
  kind: 'mobius-matrix',
  vec4s: 4,
  pack: (e) => [...e.a, ...e.b, ...e.c, ...e.d, ...packRegion(e.forward), ...packRegion(e.backward)],
  step: glslStepBlock(
    `
if (inRegion(d2, p)) {
  applyMobius(p, s, d0.xy, d0.zw, d1.xy, d1.zw, 1.0);
  continue;
} else if (inRegion(d3, p)) {
  applyMobius(p, s, d1.zw, d0.zw, d1.xy, d0.xy, -1.0);
  continue;
}`,
    [inRegionGlsl, applyMobiusGlsl],
  ),
  inside: glslFunction(
    'mobiusMatrixInside',
    `
bool mobiusMatrixInside(vec2 p, ${ARGS}) {
  return inRegion(d2, p) || inRegion(d3, p);
}`,
    [inRegionGlsl],
  ),
  boundaryDistance: glslFunction(
    'mobiusMatrixBoundaryDistance',
    `
float mobiusMatrixBoundaryDistance(vec2 p, ${ARGS}) {
  return min(regionBoundaryDistance(d2, p), regionBoundaryDistance(d3, p));
}`,
    [regionBoundaryDistanceGlsl],
  ),
};
