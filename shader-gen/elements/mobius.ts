/**
 * Two-circle Möbius generator: in A, g = σ_C2∘σ_C1 (σ_C1 first); else in B, g⁻¹ = σ_C1∘σ_C2.
 * A is always tested before B (docs/math.md). Scale: the product of both inversions' factors.
 * GLSL packing (4 vec4):
 *   d0 = (C1.c.x, C1.c.y, C1.r, 0), d1 = (C2.c.x, C2.c.y, C2.r, 0),
 *   d2 = region A, d3 = region B (each (c.x, c.y, r, outside), see disk-region.ts).
 */
import type { MobiusElement } from '../../nodes/core/scene.ts';
import { glslFunction } from '../glsl/snippet.ts';
import {
  inRegion,
  inRegionGlsl,
  packRegion,
  regionBoundaryDistance,
  regionBoundaryDistanceGlsl,
} from './disk-region.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';
import { invertState, invertStateGlsl } from './inversion.ts';

export const mobius: ElementRecord<MobiusElement> = {
  kind: 'mobius',
  cpu: {
    step(e, st) {
      const { c1, c2 } = e;
      if (inRegion(e.a, st.x, st.y)) {
        invertState(st, c1.c[0], c1.c[1], c1.r);
        invertState(st, c2.c[0], c2.c[1], c2.r);
      } else if (inRegion(e.b, st.x, st.y)) {
        invertState(st, c2.c[0], c2.c[1], c2.r);
        invertState(st, c1.c[0], c1.c[1], c1.r);
      } else return false;
      st.depth += 1;
      return true;
    },
    inside: (e, x, y) => inRegion(e.a, x, y) || inRegion(e.b, x, y),
    boundaryDistance: (e, x, y) =>
      Math.min(regionBoundaryDistance(e.a, x, y), regionBoundaryDistance(e.b, x, y)),
  },
  glsl: {
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
  },
};
