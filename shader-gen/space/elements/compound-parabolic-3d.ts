/**
 * Compound parabolic generator (docs/math-3d.md §6): s = (x − q)·n; s < 0 → G(x) = R_θ(x + 2h n);
 * s > 2h → G⁻¹(x) = R_−θ(x) − 2h n; the slab between is its fundamental domain. An isometry: no
 * records. Rodrigues about the axis (q, n): v cosθ + (n × v) sinθ + n(n·v)(1 − cosθ), v = x − q.
 * GLSL packing (3 vec4): d0 = (q, h), d1 = (n, 0), d2 = (cosθ, sinθ, 0, 0).
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import type { ElementRecord3d, Walk3dState } from './element-3d-kind.ts';

type Parabolic = Extract<Element3d, { kind: 'compound-parabolic-3d' }>;

const slab = ({ g }: Parabolic, x: number, y: number, z: number): number =>
  (x - g.point[0]) * g.normal[0] + (y - g.point[1]) * g.normal[1] + (z - g.point[2]) * g.normal[2];

/** Rotates the state's point about the axis (q, n) by the angle with cosine c and sine s. */
function rotate(st: Walk3dState, q: readonly number[], n: readonly number[], c: number, s: number): void {
  const vx = st.x - q[0]!;
  const vy = st.y - q[1]!;
  const vz = st.z - q[2]!;
  const nv = n[0]! * vx + n[1]! * vy + n[2]! * vz;
  const cx = n[1]! * vz - n[2]! * vy;
  const cy = n[2]! * vx - n[0]! * vz;
  const cz = n[0]! * vy - n[1]! * vx;
  st.x = q[0]! + vx * c + cx * s + n[0]! * nv * (1 - c);
  st.y = q[1]! + vy * c + cy * s + n[1]! * nv * (1 - c);
  st.z = q[2]! + vz * c + cz * s + n[2]! * nv * (1 - c);
}

const rotateGlsl = glslFunction(
  'rotateAxis',
  `
vec3 rotateAxis(vec3 p, vec3 q, vec3 n, float c, float s) {
  vec3 v = p - q;
  return q + v * c + cross(n, v) * s + n * (dot(n, v) * (1.0 - c));
}`,
);

export const compoundParabolic3d: ElementRecord3d<Parabolic> = {
  kind: 'compound-parabolic-3d',
  inversionsPerStep: 0,
  cpu: {
    step(e, st) {
      const { point: q, normal: n, gap: h, torsion } = e.g;
      const sd = slab(e, st.x, st.y, st.z);
      const c = Math.cos(torsion);
      const s = Math.sin(torsion);
      if (sd < 0) {
        st.x += 2 * h * n[0];
        st.y += 2 * h * n[1];
        st.z += 2 * h * n[2];
        rotate(st, q, n, c, s);
      } else if (sd > 2 * h) {
        rotate(st, q, n, c, -s);
        st.x -= 2 * h * n[0];
        st.y -= 2 * h * n[1];
        st.z -= 2 * h * n[2];
      } else return false;
      st.depth += 1;
      return true;
    },
    regionDistance: (e, x, y, z) => {
      const sd = slab(e, x, y, z);
      return Math.max(0, Math.min(sd, 2 * e.g.gap - sd));
    },
  },
  glsl: {
    vec4s: 3,
    pack: ({ g }) => [...g.point, g.gap, ...g.normal, 0, Math.cos(g.torsion), Math.sin(g.torsion), 0, 0],
    step: () =>
      `
float sd = dot(p - d0.xyz, d1.xyz);
if (sd < 0.0) {
  p = rotateAxis(p + (2.0 * d0.w) * d1.xyz, d0.xyz, d1.xyz, d2.x, d2.y);
  depth += 1;
  continue;
}
if (sd > 2.0 * d0.w) {
  p = rotateAxis(p, d0.xyz, d1.xyz, d2.x, -d2.y) - (2.0 * d0.w) * d1.xyz;
  depth += 1;
  continue;
}`.trim(),
    regionDistance: glslFunction(
      'compoundParabolic3dRegionDistance',
      `
float compoundParabolic3dRegionDistance(vec3 p, vec4 d0, vec4 d1, vec4 d2) {
  float sd = dot(p - d0.xyz, d1.xyz);
  return max(0.0, min(sd, 2.0 * d0.w - sd));
}`,
    ),
    deps: [rotateGlsl],
  },
};
