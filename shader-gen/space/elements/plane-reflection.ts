/**
 * Reflection in a plane (q, n), n unit: region the moved side (x − q)·n < 0; ρ(x) = x − 2((x − q)·n)n,
 * factor 1 — an isometry; a tracked pole is reflected too (docs/math-3d.md §1, §7, §8).
 * GLSL packing (1 vec4): d0 = (n, −q·n), so (x − q)·n = dot(x, n) + d0.w.
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import { appliedGlsl, type ElementRecord3d } from './element-3d-kind.ts';

type PlaneReflection = Extract<Element3d, { kind: 'plane-reflection' }>;

const signed = (e: PlaneReflection, x: number, y: number, z: number): number => {
  const [qx, qy, qz] = e.plane.point;
  const [nx, ny, nz] = e.plane.normal;
  return (x - qx) * nx + (y - qy) * ny + (z - qz) * nz;
};

export const planeReflection: ElementRecord3d<PlaneReflection> = {
  kind: 'plane-reflection',
  cpu: {
    step(e, st) {
      const sd = signed(e, st.x, st.y, st.z);
      if (!(sd < 0)) return false;
      const [nx, ny, nz] = e.plane.normal;
      st.x -= 2 * sd * nx;
      st.y -= 2 * sd * ny;
      st.z -= 2 * sd * nz;
      const pole = st.pole;
      if (pole) {
        const ps = signed(e, pole.x, pole.y, pole.z);
        pole.x -= 2 * ps * nx;
        pole.y -= 2 * ps * ny;
        pole.z -= 2 * ps * nz;
      }
      st.depth += 1;
      return true;
    },
    regionDistance: (e, x, y, z) => Math.max(0, signed(e, x, y, z)),
    boundaryDistance: (e, x, y, z) => Math.abs(signed(e, x, y, z)),
    mirror(e, x, y, z, out) {
      const sd = signed(e, x, y, z);
      const [nx, ny, nz] = e.plane.normal;
      out.x = x - 2 * sd * nx;
      out.y = y - 2 * sd * ny;
      out.z = z - 2 * sd * nz;
      return 0;
    },
  },
  glsl: {
    vec4s: 1,
    pack: (e) => {
      const [qx, qy, qz] = e.plane.point;
      const [nx, ny, nz] = e.plane.normal;
      return [nx, ny, nz, -(qx * nx + qy * ny + qz * nz)];
    },
    step: ({ pole, applied }) =>
      `
float sd = dot(p, d0.xyz) + d0.w;
if (sd < 0.0) {
  p -= (2.0 * sd) * d0.xyz;${pole ? '\n  pole -= (2.0 * (dot(pole, d0.xyz) + d0.w)) * d0.xyz;' : ''}
${appliedGlsl(applied)}
}`.trim(),
    regionDistance: glslFunction(
      'planeReflectionRegionDistance',
      `
float planeReflectionRegionDistance(vec3 p, vec4 d0) {
  return max(0.0, dot(p, d0.xyz) + d0.w);
}`,
    ),
    boundaryDistance: glslFunction(
      'planeReflectionBoundaryDistance',
      `
float planeReflectionBoundaryDistance(vec3 p, vec4 d0) {
  return abs(dot(p, d0.xyz) + d0.w);
}`,
    ),
    mirror: glslFunction(
      'planeReflectionMirror',
      `
float planeReflectionMirror(vec3 p, vec4 d0, out vec3 q, out float far) {
  q = p - (2.0 * (dot(p, d0.xyz) + d0.w)) * d0.xyz;
  far = 0.0;
  return 0.0;
}`,
    ),
    deps: [],
  },
};
