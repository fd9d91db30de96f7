/**
 * Inversion in a sphere (c, r): region the open ball |x − c| < r; x ↦ c + r²(x − c)/|x − c|²,
 * factor r²/|x − c|² (docs/math-3d.md §1). GLSL packing (2 vec4): d0 = (c, r), d1 = (r², 0, 0, 0).
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import { appliedGlsl, type ElementRecord3d } from './element-3d-kind.ts';
import { dist2, inversionFactorGlsl, invertGlsl, invertWalk } from './invert.ts';

type SphereInversion = Extract<Element3d, { kind: 'sphere-inversion' }>;

/** Distance to a ball (0 inside): max(0, |x − c| − r). */
export const ballDistance = (x: number, y: number, z: number, c: readonly number[], r: number): number =>
  Math.max(0, Math.sqrt(dist2(x, y, z, c[0]!, c[1]!, c[2]!)) - r);

export const ballDistanceGlsl = glslFunction(
  'ballDistance',
  `
float ballDistance(vec3 p, vec4 ball) {
  return max(0.0, length(p - ball.xyz) - ball.w);
}`,
);

export const sphereInversion: ElementRecord3d<SphereInversion> = {
  kind: 'sphere-inversion',
  cpu: {
    step(e, st) {
      const [cx, cy, cz] = e.sphere.center;
      const r2 = e.sphere.radius * e.sphere.radius;
      if (!(dist2(st.x, st.y, st.z, cx, cy, cz) < r2)) return false;
      invertWalk(st, cx, cy, cz, r2);
      st.depth += 1;
      return true;
    },
    regionDistance: (e, x, y, z) => ballDistance(x, y, z, e.sphere.center, e.sphere.radius),
    // ||x − c| − r|: the distance to the sphere, from inside or outside.
    boundaryDistance: (e, x, y, z) => {
      const [cx, cy, cz] = e.sphere.center;
      return Math.abs(Math.sqrt(dist2(x, y, z, cx, cy, cz)) - e.sphere.radius);
    },
    mirror(e, x, y, z, out) {
      const [cx, cy, cz] = e.sphere.center;
      const r2 = e.sphere.radius * e.sphere.radius;
      out.x = x;
      out.y = y;
      out.z = z;
      out.s = 1;
      out.pole = null;
      invertWalk(out, cx, cy, cz, r2);
      return r2;
    },
  },
  glsl: {
    vec4s: 2,
    pack: (e) => [...e.sphere.center, e.sphere.radius, e.sphere.radius ** 2, 0, 0, 0],
    step: ({ pole, applied }) =>
      `
vec3 dd = p - d0.xyz;
if (dot(dd, dd) < d1.x) {
${invertGlsl('d0.xyz', 'd1.x', 'kf', pole)}
${appliedGlsl(applied)}
}`.trim(),
    regionDistance: glslFunction(
      'sphereInversionRegionDistance',
      `
float sphereInversionRegionDistance(vec3 p, vec4 d0, vec4 d1) {
  return ballDistance(p, d0);
}`,
      [ballDistanceGlsl],
    ),
    boundaryDistance: glslFunction(
      'sphereInversionBoundaryDistance',
      `
float sphereInversionBoundaryDistance(vec3 p, vec4 d0, vec4 d1) {
  return abs(length(p - d0.xyz) - d0.w);
}`,
    ),
    mirror: glslFunction(
      'sphereInversionMirror',
      `
float sphereInversionMirror(vec3 p, vec4 d0, vec4 d1, out vec3 q, out float far) {
  float kf = inversionFactor(p, d0.xyz, d1.x);
  q = d0.xyz + (p - d0.xyz) * kf;
  far = length(q - d0.xyz);
  return d1.x;
}`,
      [inversionFactorGlsl],
    ),
    deps: [inversionFactorGlsl],
  },
};
