/**
 * Orbit seeds in space (spheres and axis-aligned boxes): their signed distance, their bounding
 * ball, CPU and GLSL twins. Sphere: |x − c| − r. Box (centre c, half-extents h): with
 * q = |x − c| − h per axis, |max(q, 0)| + min(max(q.x, q.y, q.z), 0) (exact, negative inside).
 * Sphairahedron tile: nodes/geometry/space/sphairahedron-tile.ts (docs/math-3d.md "The tile as a seed").
 * GLSL packing per seed: sphere and box 2 vec4, (c, r or 0), (h or 0, kind: 0 sphere / 1 box);
 * tile 9 vec4 (packTile), read by `tileDistance`.
 */
import type { Seed3d } from '../../nodes/core/scene-3d.ts';
import {
  packTile,
  TILE_BALLS,
  TILE_PLANES,
  tileSignedDistance,
} from '../../nodes/geometry/space/sphairahedron-tile.ts';
import type { Sphere } from '../../nodes/geometry/space/sphere.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { type GlslFunction, glslFunction } from '../glsl/snippet.ts';

export function seedDistance(seed: Seed3d, x: number, y: number, z: number): number {
  // Indexing, not destructuring: this runs several times per march step of the CPU tracer.
  if (seed.kind === 'sphere') {
    const c = seed.sphere.center;
    return Math.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) - seed.sphere.radius;
  }
  if (seed.kind === 'tile') return tileSignedDistance(seed.tile, x, y, z);
  const qx = Math.abs(x - seed.center[0]) - seed.halfSize[0];
  const qy = Math.abs(y - seed.center[1]) - seed.halfSize[1];
  const qz = Math.abs(z - seed.center[2]) - seed.halfSize[2];
  const outside = Math.hypot(Math.max(qx, 0), Math.max(qy, 0), Math.max(qz, 0));
  return outside + Math.min(Math.max(qx, qy, qz), 0);
}

/** The smallest ball about the seed's centre that holds it. */
export const seedBall = (seed: Seed3d): Sphere =>
  seed.kind === 'sphere'
    ? seed.sphere
    : seed.kind === 'tile'
      ? seed.tile.bound
      : { center: seed.center, radius: Math.hypot(...seed.halfSize) };

/**
 * A length typical of the seed (its radius; a box's smallest half-extent; a finite tile's bounding
 * radius, an infinite one's unit prism): sets the AO scale.
 */
export const seedSize = (seed: Seed3d): number =>
  seed.kind === 'sphere'
    ? seed.sphere.radius
    : seed.kind === 'tile'
      ? seed.tile.inversion
        ? seed.tile.bound.radius
        : 1
      : Math.min(...seed.halfSize);

export const packSeed = (seed: Seed3d): number[] =>
  seed.kind === 'sphere'
    ? [...seed.sphere.center, seed.sphere.radius, 0, 0, 0, 0]
    : seed.kind === 'tile'
      ? packTile(seed.tile)
      : [...seed.center, 0, ...seed.halfSize, 1];

/** The GLSL call giving the seed's distance at `p` from its packed rows (the functions: seedGlslFunctions). */
export const seedDistanceCall = (seed: Seed3d, rows: readonly string[]): string =>
  `${seed.kind === 'tile' ? 'tileDistance' : 'seedDistance'}(p, ${rows.join(', ')})`;

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

const planeRows = Array.from({ length: TILE_PLANES }, (_, k) => `vec4 f${k}`);
const ballRows = Array.from({ length: TILE_BALLS }, (_, k) => `vec4 s${k}`);

/**
 * GLSL `tileDistance(p, inv, cut, f0…f3, s0…s2)`: twin of tileSignedDistance over packTile's rows
 * (padding planes and balls never win). inv.w = 0: the infinite form, q = p; else q = I(p).
 */
export const tileDistanceGlsl = glslFunction(
  'tileDistance',
  `
float tileDistance(vec3 p, vec4 inv, vec4 cut, ${[...planeRows, ...ballRows].join(', ')}) {
  vec3 q = p;
  float far = 1.0;
  float r2 = inv.w * inv.w;
  if (inv.w > 0.0) {
    vec3 v = p - inv.xyz;
    far = max(dot(v, v), 1e-24);
    q = inv.xyz + (r2 / far) * v;
  }
  float d = cut.x - q.z;
  float column = ${floatLiteral(1e30)};
${Array.from({ length: TILE_PLANES }, (_, k) => `  d = max(d, f${k}.w - dot(f${k}.xyz, q));`).join('\n')}
${Array.from(
  { length: TILE_BALLS },
  (_, k) => `  {
    float h = length(q.xy - s${k}.xy);
    d = max(d, s${k}.w - length(vec2(h, q.z - s${k}.z)));
    column = min(column, max(h - s${k}.w, q.z - s${k}.z));
  }`,
).join('\n')}
  d = max(d, column);
  if (inv.w <= 0.0) return d;
  float f = sqrt(far);
  return f * d / (r2 / f + max(d, 0.0));
}`,
);

/** The GLSL functions the seeds' distance calls need. */
export const seedGlslFunctions = (seeds: readonly Seed3d[]): GlslFunction[] => [
  seedDistanceGlsl,
  ...(seeds.some((s) => s.kind === 'tile') ? [tileDistanceGlsl] : []),
];
