/**
 * Orbit seeds in space (spheres and axis-aligned boxes): their signed distance, their bounding
 * ball, CPU and GLSL twins. Sphere: |x − c| − r. Box (centre c, half-extents h): with
 * q = |x − c| − h per axis, |max(q, 0)| + min(max(q.x, q.y, q.z), 0) (exact, negative inside).
 * GLSL packing per seed (2 vec4): (c, r or 0), (h or 0, kind: 0 sphere / 1 box).
 */
import type { Seed3d } from '../../nodes/core/scene-3d.ts';
import type { Sphere } from '../../nodes/geometry/space/sphere.ts';
import { glslFunction } from '../glsl/snippet.ts';

export function seedDistance(seed: Seed3d, x: number, y: number, z: number): number {
  // Indexing, not destructuring: this runs several times per march step of the CPU tracer.
  if (seed.kind === 'sphere') {
    const c = seed.sphere.center;
    return Math.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) - seed.sphere.radius;
  }
  const qx = Math.abs(x - seed.center[0]) - seed.halfSize[0];
  const qy = Math.abs(y - seed.center[1]) - seed.halfSize[1];
  const qz = Math.abs(z - seed.center[2]) - seed.halfSize[2];
  const outside = Math.hypot(Math.max(qx, 0), Math.max(qy, 0), Math.max(qz, 0));
  return outside + Math.min(Math.max(qx, qy, qz), 0);
}

/** The smallest ball about the seed's centre that holds it. */
export const seedBall = (seed: Seed3d): Sphere =>
  seed.kind === 'sphere' ? seed.sphere : { center: seed.center, radius: Math.hypot(...seed.halfSize) };

/** A length typical of the seed (its radius; a box's smallest half-extent): sets the AO scale. */
export const seedSize = (seed: Seed3d): number =>
  seed.kind === 'sphere' ? seed.sphere.radius : Math.min(...seed.halfSize);

export const packSeed = (seed: Seed3d): number[] =>
  seed.kind === 'sphere'
    ? [...seed.sphere.center, seed.sphere.radius, 0, 0, 0, 0]
    : [...seed.center, 0, ...seed.halfSize, 1];

/** GLSL `seedDistance(p, a, b)` over the packing above (a box when b.w > 0.5). */
export const seedDistanceGlsl = glslFunction(
  'seedDistance',
  `
float seedDistance(vec3 p, vec4 a, vec4 b) {
  if (b.w > 0.5) {
    vec3 q = abs(p - a.xyz) - b.xyz;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
  }
  return length(p - a.xyz) - a.w;
}`,
);
