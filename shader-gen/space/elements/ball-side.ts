/**
 * One side of a sphere as a region (the A and B of the two-sphere generators, docs/math-3d.md §2),
 * with σ = +1 for the open ball and −1 for the open outside:
 *   inside ⇔ σ·(|x − c|² − r²) < 0,  distance to the region = max(0, σ·(|x − c| − r)).
 * GLSL: the sphere as vec4(c, r²) and σ, r given separately.
 */
import type { BallSide } from '../../../nodes/geometry/space/mobius-3d.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import { dist2 } from './invert.ts';

export const sideSign = (b: BallSide): number => (b.inside ? 1 : -1);

export function inBallSide(b: BallSide, x: number, y: number, z: number): boolean {
  const [cx, cy, cz] = b.sphere.center;
  return sideSign(b) * (dist2(x, y, z, cx, cy, cz) - b.sphere.radius ** 2) < 0;
}

export function ballSideDistance(b: BallSide, x: number, y: number, z: number): number {
  const [cx, cy, cz] = b.sphere.center;
  return Math.max(0, sideSign(b) * (Math.sqrt(dist2(x, y, z, cx, cy, cz)) - b.sphere.radius));
}

/** The packed row (c, r²) of a sphere. */
export const sphereRow = (s: { center: readonly number[]; radius: number }): number[] => [
  s.center[0]!,
  s.center[1]!,
  s.center[2]!,
  s.radius * s.radius,
];

export const inBallSideGlsl = glslFunction(
  'inBallSide',
  `
bool inBallSide(vec3 p, vec4 sphere, float sigma) {
  vec3 d = p - sphere.xyz;
  return sigma * (dot(d, d) - sphere.w) < 0.0;
}`,
);

export const ballSideDistanceGlsl = glslFunction(
  'ballSideDistance',
  `
float ballSideDistance(vec3 p, vec3 c, float r, float sigma) {
  return max(0.0, sigma * (length(p - c) - r));
}`,
);
