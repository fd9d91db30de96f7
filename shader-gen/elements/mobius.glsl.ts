/**
 * GLSL twin of mobius.ts. Packing (4 vec4):
 *   d0 = (C1.c.x, C1.c.y, C1.r, 0), d1 = (C2.c.x, C2.c.y, C2.r, 0),
 *   d2 = region A, d3 = region B (each (c.x, c.y, r, outside), see disk-region.glsl.ts).
 */
import type { MobiusElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { inRegionGlsl, packRegion, regionBoundaryDistanceGlsl } from './disk-region.glsl.ts';
import { invertStateGlsl } from './inversion.glsl.ts';

export const mobiusGlsl: GlslElementTwin<MobiusElement> = {
  kind: 'mobius',
  vec4s: 4,
  pack: (e) => [
    e.c1.c[0],
    e.c1.c[1],
    e.c1.r,
    0,
    e.c2.c[0],
    e.c2.c[1],
    e.c2.r,
    0,
    ...packRegion(e.a),
    ...packRegion(e.b),
  ],
  step: glslStepBlock(
    `
if (inRegion(d2, p)) {
  invertState(p, s, d0.xy, d0.z, d0.z * d0.z);
  invertState(p, s, d1.xy, d1.z, d1.z * d1.z);
  continue;
} else if (inRegion(d3, p)) {
  invertState(p, s, d1.xy, d1.z, d1.z * d1.z);
  invertState(p, s, d0.xy, d0.z, d0.z * d0.z);
  continue;
}`,
    [inRegionGlsl, invertStateGlsl],
  ),
  inside: glslFunction(
    'mobiusInside',
    `
bool mobiusInside(vec2 p, vec4 d0, vec4 d1, vec4 d2, vec4 d3) {
  return inRegion(d2, p) || inRegion(d3, p);
}`,
    [inRegionGlsl],
  ),
  boundaryDistance: glslFunction(
    'mobiusBoundaryDistance',
    `
float mobiusBoundaryDistance(vec2 p, vec4 d0, vec4 d1, vec4 d2, vec4 d3) {
  return min(regionBoundaryDistance(d2, p), regionBoundaryDistance(d3, p));
}`,
    [regionBoundaryDistanceGlsl],
  ),
};
