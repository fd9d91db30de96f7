/**
 * Two-sphere generator G = I_S2 ∘ I_S1 (docs/math-3d.md §2): inside A → I_S1 then I_S2; else
 * inside B → G⁻¹ = I_S1 ∘ I_S2. Two inversion records per application (the fallback bound of
 * docs/math-3d.md "§8 The tracer's distance bound" composes through them). GLSL packing (4 vec4): d0 = (c1, r1²), d1 = (c2, r2²),
 * d2 = (c1', r1'²) (S1' bounds B), d3 = (σA, σB, r1, r1').
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

type Mobius = Extract<Element3d, { kind: 'mobius-3d' }>;

export const mobius3d: ElementRecord3d<Mobius> = {
  kind: 'mobius-3d',
  cpu: {
    step({ g }, st) {
      const [first, second] = inBallSide(g.a, st.x, st.y, st.z)
        ? [g.s1, g.s2]
        : inBallSide(g.b, st.x, st.y, st.z)
          ? [g.s2, g.s1]
          : [null, null];
      if (!first || !second) return false;
      for (const s of [first, second]) invertWalk(st, ...s.center, s.radius ** 2);
      st.depth += 1;
      return true;
    },
    regionDistance: ({ g }, x, y, z) =>
      Math.min(ballSideDistance(g.a, x, y, z), ballSideDistance(g.b, x, y, z)),
  },
  glsl: {
    vec4s: 4,
    pack: ({ g }) => [
      ...sphereRow(g.s1),
      ...sphereRow(g.s2),
      ...sphereRow(g.s1Image),
      sideSign(g.a),
      sideSign(g.b),
      g.a.sphere.radius,
      g.b.sphere.radius,
    ],
    step: ({ pole, applied }) =>
      `
if (inBallSide(p, d0, d3.x)) {
${invertGlsl('d0.xyz', 'd0.w', 'ka', pole)}
${invertGlsl('d1.xyz', 'd1.w', 'kb', pole)}
${appliedGlsl(applied)}
}
if (inBallSide(p, d2, d3.y)) {
${invertGlsl('d1.xyz', 'd1.w', 'kc', pole)}
${invertGlsl('d0.xyz', 'd0.w', 'kd', pole)}
${appliedGlsl(applied)}
}`.trim(),
    regionDistance: glslFunction(
      'mobius3dRegionDistance',
      `
float mobius3dRegionDistance(vec3 p, vec4 d0, vec4 d1, vec4 d2, vec4 d3) {
  return min(ballSideDistance(p, d0.xyz, d3.z, d3.x), ballSideDistance(p, d2.xyz, d3.w, d3.y));
}`,
      [ballSideDistanceGlsl],
    ),
    deps: [inBallSideGlsl, inversionFactorGlsl],
  },
};
