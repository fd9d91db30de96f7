/**
 * Box fold (docs/math-3d.md §10): region the open outside of the box (c, h); the step folds the point
 * into the box by reflecting it in the box's faces, per axis the triangle wave u ↦ σu + τ of
 * nodes/geometry/space/box-fold.ts (u = x − c; k = ⌊(u + h)/4h⌋, w = u + h − 4hk; σ = −1 when
 * w ≥ 2h, else +1; τ = −σ·4hk + (1 − σ)h). A product of plane reflections, so an isometry: factor 1,
 * and a tracked pole moves by the same σ, τ (the map chosen at the point), as §8 requires.
 * GLSL packing (2 vec4): d0 = (c, 0), d1 = (h, 0).
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { axisFold } from '../../../nodes/geometry/space/box-fold.ts';
import { GLSL_FAR } from '../../glsl/iis.glsl.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import { appliedGlsl, type ElementRecord3d, type Walk3dState } from './element-3d-kind.ts';

type BoxFoldElement = Extract<Element3d, { kind: 'box-fold' }>;

type Point = Pick<Walk3dState, 'x' | 'y' | 'z'>;
const AXES = ['x', 'y', 'z'] as const;

const outside = ({ box }: BoxFoldElement, p: Point): boolean =>
  AXES.some((a, k) => Math.abs(p[a] - box.center[k]) > box.halfSize[k]);

export const boxFold: ElementRecord3d<BoxFoldElement> = {
  kind: 'box-fold',
  cpu: {
    step(e, st) {
      if (!outside(e, st)) return false;
      const { center: c, halfSize: h } = e.box;
      AXES.forEach((a, k) => {
        const f = axisFold(st[a] - c[k], h[k]);
        st[a] = c[k] + f.sign * (st[a] - c[k]) + f.shift;
        if (st.pole) st.pole[a] = c[k] + f.sign * (st.pole[a] - c[k]) + f.shift;
      });
      st.depth += 1;
      return true;
    },
    regionDistance: ({ box }, x, y, z) =>
      Math.max(
        0,
        Math.min(
          box.halfSize[0] - Math.abs(x - box.center[0]),
          box.halfSize[1] - Math.abs(y - box.center[1]),
          box.halfSize[2] - Math.abs(z - box.center[2]),
        ),
      ),
    // In the closed box the region's orbit is never nearer than the box's own (§10): no cover.
    endCover: (e, x, y, z) => (outside(e, { x, y, z }) ? 0 : Number.POSITIVE_INFINITY),
  },
  glsl: {
    vec4s: 2,
    pack: ({ box }) => [...box.center, 0, ...box.halfSize, 0],
    step: ({ pole, applied }) =>
      `
vec3 u = p - d0.xyz;
if (any(greaterThan(abs(u), d1.xyz))) {
  vec3 period = 4.0 * d1.xyz;
  vec3 k = floor((u + d1.xyz) / period);
  vec3 sg = 1.0 - 2.0 * step(2.0 * d1.xyz, u + d1.xyz - k * period);
  vec3 tau = (1.0 - sg) * d1.xyz - sg * k * period;
  p = d0.xyz + sg * u + tau;${pole ? '\n  pole = d0.xyz + sg * (pole - d0.xyz) + tau;' : ''}
${appliedGlsl(applied)}
}`.trim(),
    regionDistance: glslFunction(
      'boxFoldRegionDistance',
      `
float boxFoldRegionDistance(vec3 p, vec4 d0, vec4 d1) {
  vec3 q = d1.xyz - abs(p - d0.xyz);
  return max(0.0, min(q.x, min(q.y, q.z)));
}`,
    ),
    endCover: glslFunction(
      'boxFoldEndCover',
      `
float boxFoldEndCover(vec3 p, vec4 d0, vec4 d1) {
  return any(greaterThan(abs(p - d0.xyz), d1.xyz)) ? 0.0 : ${GLSL_FAR};
}`,
    ),
    deps: [],
  },
};
