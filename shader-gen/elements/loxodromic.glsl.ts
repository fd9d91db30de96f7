/**
 * GLSL twin of loxodromic.ts. Packing (6 vec4):
 *   d0 = (C1.c, C1.r, 0), d1 = (C2.c, C2.r, 0), d2 = (C3.c, C3.r, 0),
 *   d3 = (L.q.x, L.q.y, L.n.x, L.n.y), d4 = region A, d5 = region B (see disk-region.glsl.ts).
 */
import type { LoxodromicElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { inRegionGlsl, packRegion, regionBoundaryDistanceGlsl } from './disk-region.glsl.ts';
import { invertStateGlsl } from './inversion.glsl.ts';
import { reflectStateGlsl } from './reflection.glsl.ts';

const circle = (c: LoxodromicElement['c1']) => [c.c[0], c.c[1], c.r, 0];
const ARGS = 'vec4 d0, vec4 d1, vec4 d2, vec4 d3, vec4 d4, vec4 d5';

export const loxodromicGlsl: GlslElementTwin<LoxodromicElement> = {
  kind: 'loxodromic',
  vec4s: 6,
  pack: (e) => [
    ...circle(e.c1),
    ...circle(e.c2),
    ...circle(e.c3),
    e.lq[0],
    e.lq[1],
    e.ln[0],
    e.ln[1],
    ...packRegion(e.a),
    ...packRegion(e.b),
  ],
  step: glslStepBlock(
    `
if (inRegion(d4, p)) {
  reflectState(p, d3.xy, d3.zw);
  invertState(p, s, d2.xy, d2.z, d2.z * d2.z);
  invertState(p, s, d0.xy, d0.z, d0.z * d0.z);
  invertState(p, s, d1.xy, d1.z, d1.z * d1.z);
  continue;
} else if (inRegion(d5, p)) {
  invertState(p, s, d1.xy, d1.z, d1.z * d1.z);
  invertState(p, s, d0.xy, d0.z, d0.z * d0.z);
  invertState(p, s, d2.xy, d2.z, d2.z * d2.z);
  reflectState(p, d3.xy, d3.zw);
  continue;
}`,
    [inRegionGlsl, invertStateGlsl, reflectStateGlsl],
  ),
  inside: glslFunction(
    'loxodromicInside',
    `
bool loxodromicInside(vec2 p, ${ARGS}) {
  return inRegion(d4, p) || inRegion(d5, p);
}`,
    [inRegionGlsl],
  ),
  boundaryDistance: glslFunction(
    'loxodromicBoundaryDistance',
    `
float loxodromicBoundaryDistance(vec2 p, ${ARGS}) {
  return min(regionBoundaryDistance(d4, p), regionBoundaryDistance(d5, p));
}`,
    [regionBoundaryDistanceGlsl],
  ),
};
