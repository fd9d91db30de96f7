/**
 * Orbit seeds in space (spheres, axis-aligned boxes and formula solids): their signed distance,
 * their bounding ball, CPU and GLSL twins. Sphere: |x − c| − r. Box (centre c, half-extents h): with
 * q = |x − c| − h per axis, |max(q, 0)| + min(max(q.x, q.y, q.z), 0) (exact, negative inside).
 * GLSL packing per seed (2 vec4): (c, r or 0), (h or 0, kind: 0 sphere / 1 box).
 */
import type { Seed3d } from '../../nodes/core/scene-3d.ts';
import { checkedFormula } from '../../nodes/formula/checked.ts';
import { SOLID_NAMES } from '../../nodes/formula/names.ts';
import { FormulaError } from '../../nodes/formula/parse.ts';
import { solidSeedDistance } from '../../nodes/formula/solid.ts';
import type { Sphere } from '../../nodes/geometry/space/sphere.ts';
import { formulaGlsl } from '../glsl/formula.glsl.ts';
import { type GlslFunction, glslFunction } from '../glsl/snippet.ts';

export function seedDistance(seed: Seed3d, x: number, y: number, z: number): number {
  // Indexing, not destructuring: this runs several times per march step of the CPU tracer.
  if (seed.kind === 'formula') return solidSeedDistance(seed, x, y, z);
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
  seed.kind === 'sphere'
    ? seed.sphere
    : seed.kind === 'formula'
      ? { center: seed.center, radius: seed.radius }
      : { center: seed.center, radius: Math.hypot(...seed.halfSize) };

/**
 * A length typical of the seed (its radius; a box's smallest half-extent; a quarter of a solid's
 * bounding radius, its parts being smaller than the ball): sets the AO scale.
 */
export const seedSize = (seed: Seed3d): number =>
  seed.kind === 'sphere'
    ? seed.sphere.radius
    : seed.kind === 'formula'
      ? seed.radius / 4
      : Math.min(...seed.halfSize);

/** Two vec4 per seed: sphere (c, r), (0); box (c, 0), (h, 1); solid (c, R), (a, b, c, L). */
export const packSeed = (seed: Seed3d): number[] =>
  seed.kind === 'sphere'
    ? [...seed.sphere.center, seed.sphere.radius, 0, 0, 0, 0]
    : seed.kind === 'formula'
      ? [...seed.center, seed.radius, ...seed.numbers, seed.slope]
      : [...seed.center, 0, ...seed.halfSize, 1];

const SOLID_GLSL_NAMES = { x: 'q.x', y: 'q.y', z: 'q.z', a: 'k.x', b: 'k.y', c: 'k.z' } as const;

/**
 * The GLSL distance of seed `index` at p over its two packed rows `a`, `b` (GLSL expressions):
 * `seedDistance(p, a, b)` for spheres and boxes; for a solid a function of its own, written from
 * its checked formula tree (../glsl/formula.glsl.ts: nothing of the text is pasted), with the
 * CPU's formula (nodes/formula/solid.ts: max(f(p − c)/L, b) in the ball, max(b, f(p′ − c)/L − b) outside). A solid whose formula does
 * not check never reaches a scene (the node fails), so `run` is always there.
 */
export function seedGlsl(
  seed: Seed3d,
  index: number,
): { readonly fn: GlslFunction; readonly deps: readonly GlslFunction[] } {
  if (seed.kind !== 'formula') return { fn: seedDistanceGlsl, deps: [] };
  const checked = checkedFormula(seed.formula, SOLID_NAMES);
  if (checked instanceof FormulaError) throw new Error(`seed solid ${seed.nodeId}: ${checked.message}`);
  const body = formulaGlsl(checked.tree, SOLID_GLSL_NAMES);
  const name = `seedSolid${index}`;
  const fn = glslFunction(
    name,
    `
float ${name}(vec3 p, vec4 a, vec4 k) {
  vec3 u = p - a.xyz;
  float len = length(u);
  float ball = len - a.w;
  vec3 q = ball < 0.0 ? u : u * (a.w / max(len, 1e-30));
  float f = (${body.expr}) / k.w;
  if (ball < 0.0) return isnan(f) ? 0.0 : max(f, ball);
  return isnan(f) ? ball : max(ball, f - ball);
}`,
  );
  return { fn, deps: body.deps };
}

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
