/**
 * Compound loxodromic generator (docs/math-3d.md §3): the regions of its base two-sphere map;
 * inside A → I_S1, I_S2, I_S3, I_S4 in that order; inside B → I_S4, I_S3, I_S2, I_S1. Four
 * inversion records per application. GLSL packing (6 vec4): d0..d3 = (c_k, r_k²) for S1..S4,
 * d4 = (c1', r1'²), d5 = (σA, σB, r1, r1').
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import {
  ballSideDistance,
  ballSideDistanceGlsl,
  inBallSide,
  inBallSideGlsl,
  sideSign,
  sphereRow,
} from './ball-side.ts';
import { appliedGlsl, type ElementRecord3d } from './element-3d-kind.ts';
import { inversionFactorGlsl, invertGlsl, invertWalk } from './invert.ts';

type Loxodromic = Extract<Element3d, { kind: 'compound-loxodromic-3d' }>;

const chain = (rows: readonly string[], pole: boolean, tag: string) =>
  rows.map((d, k) => invertGlsl(`${d}.xyz`, `${d}.w`, `k${tag}${k}`, pole)).join('\n');

export const compoundLoxodromic3d: ElementRecord3d<Loxodromic> = {
  kind: 'compound-loxodromic-3d',
  cpu: {
    step({ g }, st) {
      const spheres = [g.base.s1, g.base.s2, g.s3, g.s4];
      const order = inBallSide(g.base.a, st.x, st.y, st.z)
        ? spheres
        : inBallSide(g.base.b, st.x, st.y, st.z)
          ? spheres.reverse()
          : null;
      if (!order) return false;
      for (const s of order) invertWalk(st, ...s.center, s.radius ** 2);
      st.depth += 1;
      return true;
    },
    regionDistance: ({ g }, x, y, z) =>
      Math.min(ballSideDistance(g.base.a, x, y, z), ballSideDistance(g.base.b, x, y, z)),
  },
  glsl: {
    vec4s: 6,
    pack: ({ g }) => [
      ...sphereRow(g.base.s1),
      ...sphereRow(g.base.s2),
      ...sphereRow(g.s3),
      ...sphereRow(g.s4),
      ...sphereRow(g.base.s1Image),
      sideSign(g.base.a),
      sideSign(g.base.b),
      g.base.a.sphere.radius,
      g.base.b.sphere.radius,
    ],
    step: ({ pole, applied }) =>
      `
if (inBallSide(p, d0, d5.x)) {
${chain(['d0', 'd1', 'd2', 'd3'], pole, 'a')}
${appliedGlsl(applied)}
}
if (inBallSide(p, d4, d5.y)) {
${chain(['d3', 'd2', 'd1', 'd0'], pole, 'b')}
${appliedGlsl(applied)}
}`.trim(),
    regionDistance: glslFunction(
      'compoundLoxodromic3dRegionDistance',
      `
float compoundLoxodromic3dRegionDistance(vec3 p, vec4 d0, vec4 d1, vec4 d2, vec4 d3, vec4 d4, vec4 d5) {
  return min(ballSideDistance(p, d0.xyz, d5.z, d5.x), ballSideDistance(p, d4.xyz, d5.w, d5.y));
}`,
      [ballSideDistanceGlsl],
    ),
    deps: [inBallSideGlsl, inversionFactorGlsl],
  },
};
