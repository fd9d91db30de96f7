/**
 * Compound parabolic generator (docs/math-3d.md §6): s = (x − q)·n; s < 0 → G(x) = R_θ(x + 2h n);
 * s > 2h → G⁻¹(x) = R_−θ(x) − 2h n; the slab between is its fundamental domain. An isometry: a
 * tracked pole moves with the point (docs/math-3d.md §8). Rodrigues about the axis (q, n): v cosθ + (n × v) sinθ + n(n·v)(1 − cosθ), v = x − q.
 * GLSL packing (3 vec4): d0 = (q, h), d1 = (n, 0), d2 = (cosθ, sinθ, 0, 0).
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import { appliedGlsl, type ElementRecord3d, type Walk3dState } from './element-3d-kind.ts';

type Parabolic = Extract<Element3d, { kind: 'compound-parabolic-3d' }>;

const slab = ({ g }: Parabolic, x: number, y: number, z: number): number =>
  (x - g.point[0]) * g.normal[0] + (y - g.point[1]) * g.normal[1] + (z - g.point[2]) * g.normal[2];

type Point = Pick<Walk3dState, 'x' | 'y' | 'z'>;

/** Rotates a point about the axis (q, n) by the angle with cosine c and sine s. */
function rotate(st: Point, q: readonly number[], n: readonly number[], c: number, s: number): void {
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

/** G (dir 1: translate, then turn) or G⁻¹ (dir −1: turn back, then translate back) of a point. */
function move({ g }: Parabolic, pt: Point, dir: 1 | -1): void {
  const { point: q, normal: n, gap: h } = g;
  const c = Math.cos(g.torsion);
  const s = Math.sin(g.torsion);
  const shift = () => {
    pt.x += dir * 2 * h * n[0];
    pt.y += dir * 2 * h * n[1];
    pt.z += dir * 2 * h * n[2];
  };
  if (dir === 1) shift();
  rotate(pt, q, n, c, dir * s);
  if (dir === -1) shift();
}

export const compoundParabolic3d: ElementRecord3d<Parabolic> = {
  kind: 'compound-parabolic-3d',
  cpu: {
    step(e, st) {
      const sd = slab(e, st.x, st.y, st.z);
      const dir = sd < 0 ? 1 : sd > 2 * e.g.gap ? -1 : 0;
      if (dir === 0) return false;
      move(e, st, dir);
      if (st.pole) move(e, st.pole, dir);
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
    step: ({ pole, applied }) => {
      const forward = (v: string) =>
        `${v} = rotateAxis(${v} + (2.0 * d0.w) * d1.xyz, d0.xyz, d1.xyz, d2.x, d2.y);`;
      const back = (v: string) =>
        `${v} = rotateAxis(${v}, d0.xyz, d1.xyz, d2.x, -d2.y) - (2.0 * d0.w) * d1.xyz;`;
      const both = (f: (v: string) => string) =>
        [f('p'), ...(pole ? [f('pole')] : [])].map((l) => `  ${l}`).join('\n');
      return `
float sd = dot(p - d0.xyz, d1.xyz);
if (sd < 0.0) {
${both(forward)}
${appliedGlsl(applied)}
}
if (sd > 2.0 * d0.w) {
${both(back)}
${appliedGlsl(applied)}
}`.trim();
    },
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
