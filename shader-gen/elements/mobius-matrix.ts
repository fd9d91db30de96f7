/**
 * Möbius map from a det-1 matrix, Ford-domain rule (docs/math.md "Möbius from a matrix"): inside the
 * isometric circle I(g) (centre −d/c) apply g(z) = (az + b)/(cz + d), scale 1/|cz + d|²; else inside
 * I(g⁻¹) (centre a/c) apply g⁻¹(z) = (dz − b)/(−cz + a), scale 1/|−cz + a|². I(g) is tested first.
 * GLSL packing (4 vec4): d0 = (a.re, a.im, b.re, b.im),
 * d1 = (c.re, c.im, d.re, d.im), d2 = region I(g) (forward), d3 = region I(g⁻¹) (backward).
 */
import type { MobiusMatrixElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import { glslFunction } from '../glsl/snippet.ts';
import {
  inRegion,
  inRegionGlsl,
  packRegion,
  regionBoundaryDistance,
  regionBoundaryDistanceGlsl,
} from './disk-region.ts';
import { type ElementRecord, glslStepBlock, type IisState } from './element-kind.ts';

/**
 * z ← (p z + q)/(r z + t) for complex p, q, r, t, s *= 1/|r z + t|²: the quotient written out in
 * reals, num·conj(den)/|den|².
 */
function applyMobius(st: IisState, p: Vec2, q: Vec2, r: Vec2, t: Vec2, sign: number): void {
  const { x, y } = st;
  const nx = p[0] * x - p[1] * y + sign * q[0];
  const ny = p[0] * y + p[1] * x + sign * q[1];
  const dx = sign * (r[0] * x - r[1] * y) + t[0];
  const dy = sign * (r[0] * y + r[1] * x) + t[1];
  const d2 = dx * dx + dy * dy;
  st.x = (nx * dx + ny * dy) / d2;
  st.y = (ny * dx - nx * dy) / d2;
  st.s /= d2;
}

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

export const mobiusMatrix: ElementRecord<MobiusMatrixElement> = {
  kind: 'mobius-matrix',
  cpu: {
    step(e, st) {
      if (inRegion(e.forward, st.x, st.y)) applyMobius(st, e.a, e.b, e.c, e.d, 1);
      else if (inRegion(e.backward, st.x, st.y)) applyMobius(st, e.d, e.b, e.c, e.a, -1);
      else return false;
      st.depth += 1;
      return true;
    },
    inside: (e, x, y) => inRegion(e.forward, x, y) || inRegion(e.backward, x, y),
    boundaryDistance: (e, x, y) =>
      Math.min(regionBoundaryDistance(e.forward, x, y), regionBoundaryDistance(e.backward, x, y)),
  },
  glsl: {
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
  },
};
