/**
 * Loxodromic generator (docs/math.md): inside A, p ← σ_C2(σ_C1(σ_C3(ρ_L(p)))) (ρ_L first); else inside
 * B, p ← ρ_L(σ_C3(σ_C1(σ_C2(p)))) (σ_C2 first). +1 per application.
 * GLSL packing (6 vec4):
 *   d0 = (C1.c, C1.r, 0), d1 = (C2.c, C2.r, 0), d2 = (C3.c, C3.r, 0),
 *   d3 = (L.q.x, L.q.y, L.n.x, L.n.y), d4 = region A, d5 = region B (see disk-region.ts).
 */
import type { LoxodromicElement } from '../../nodes/core/scene.ts';
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
import { reflectState, reflectStateGlsl } from './reflection.ts';

const circle = (c: LoxodromicElement['c1']) => [c.c[0], c.c[1], c.r, 0];
const ARGS = 'vec4 d0, vec4 d1, vec4 d2, vec4 d3, vec4 d4, vec4 d5';

export const loxodromic: ElementRecord<LoxodromicElement> = {
  kind: 'loxodromic',
  cpu: {
    step(e, st) {
      const { c1, c2, c3, lq, ln } = e;
      if (inRegion(e.a, st.x, st.y)) {
        reflectState(st, lq[0], lq[1], ln[0], ln[1]);
        invertState(st, c3.c[0], c3.c[1], c3.r);
        invertState(st, c1.c[0], c1.c[1], c1.r);
        invertState(st, c2.c[0], c2.c[1], c2.r);
      } else if (inRegion(e.b, st.x, st.y)) {
        invertState(st, c2.c[0], c2.c[1], c2.r);
        invertState(st, c1.c[0], c1.c[1], c1.r);
        invertState(st, c3.c[0], c3.c[1], c3.r);
        reflectState(st, lq[0], lq[1], ln[0], ln[1]);
      } else return false;
      st.depth += 1;
      return true;
    },
    inside: (e, x, y) => inRegion(e.a, x, y) || inRegion(e.b, x, y),
    boundaryDistance: (e, x, y) =>
      Math.min(regionBoundaryDistance(e.a, x, y), regionBoundaryDistance(e.b, x, y)),
  },
  glsl: {
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
  },
};
