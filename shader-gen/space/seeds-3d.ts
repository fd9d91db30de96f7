/**
 * Orbit seeds in space (spheres, axis-aligned boxes, formula solids and sphairahedron tiles): their signed distance,
 * their bounding ball, CPU and GLSL twins. Sphere: |x − c| − r. Box (centre c, half-extents h): with
 * q = |x − c| − h per axis, |max(q, 0)| + min(max(q.x, q.y, q.z), 0) (exact, negative inside).
 * Sphairahedron tile: nodes/geometry/space/sphairahedron-tile.ts (docs/math-3d.md "The tile as a seed").
 * GLSL packing per seed: sphere and box 2 vec4, (c, r or 0), (h or 0, kind: 0 sphere / 1 box — the
 * GLSL function is chosen by kind when generated, so the flag is only the packing's);
 * tile 9 vec4 (packTile), read by `tileDistance`.
 */
import type { Seed3d } from '../../nodes/core/scene-3d.ts';
import { checkedFormula } from '../../nodes/formula/checked.ts';
import { SOLID_NAMES } from '../../nodes/formula/names.ts';
import { FormulaError } from '../../nodes/formula/parse.ts';
import { solidSeedDistance } from '../../nodes/formula/solid.ts';
import {
  packTile,
  TILE_BALLS,
  TILE_PLANES,
  tileSignedDistance,
} from '../../nodes/geometry/space/sphairahedron-tile.ts';
import type { Sphere } from '../../nodes/geometry/space/sphere.ts';
import { formulaGlsl } from '../glsl/formula.glsl.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { type GlslFunction, glslFunction } from '../glsl/snippet.ts';

export function seedDistance(seed: Seed3d, x: number, y: number, z: number): number {
  // Indexing, not destructuring: this runs several times per march step of the CPU tracer.
  if (seed.kind === 'formula') return solidSeedDistance(seed, x, y, z);
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
    : seed.kind === 'formula'
      ? { center: seed.center, radius: seed.radius }
      : seed.kind === 'tile'
        ? seed.tile.bound
        : { center: seed.center, radius: Math.hypot(...seed.halfSize) };

/**
 * A length typical of the seed (its radius; a box's smallest half-extent; a quarter of a solid's
 * bounding radius, its parts being smaller than the ball; a finite tile's bounding radius, an
 * infinite one's unit prism): sets the AO scale.
 */
export const seedSize = (seed: Seed3d): number =>
  seed.kind === 'sphere'
    ? seed.sphere.radius
    : seed.kind === 'formula'
      ? seed.radius / 4
      : seed.kind === 'tile'
        ? seed.tile.inversion
          ? seed.tile.bound.radius
          : 1
        : Math.min(...seed.halfSize);

/** Two vec4 per seed: sphere (c, r), (0); box (c, 0), (h, 1); solid (c, R), (a, b, c, L). */
export const packSeed = (seed: Seed3d): number[] =>
  seed.kind === 'sphere'
    ? [...seed.sphere.center, seed.sphere.radius, 0, 0, 0, 0]
    : seed.kind === 'formula'
      ? [...seed.center, seed.radius, ...seed.numbers, seed.slope]
      : seed.kind === 'tile'
        ? packTile(seed.tile)
        : [...seed.center, 0, ...seed.halfSize, 1];

const SOLID_GLSL_NAMES = { x: 'q.x', y: 'q.y', z: 'q.z', a: 'k.x', b: 'k.y', c: 'k.z' } as const;

/**
 * The GLSL distance function of a solid seed, number `index` in the scene, over its two packed rows
 * (c, R), (a, b, c, L): written from its checked formula tree (../glsl/formula.glsl.ts: nothing of
 * the text is pasted), with the CPU's formula (nodes/formula/solid.ts: max(f(p − c)/L, b) in the
 * ball, max(b, f(p′ − c)/L − b) outside). A solid whose formula does not check never reaches a
 * scene (the node fails).
 */
function solidGlsl(seed: Extract<Seed3d, { kind: 'formula' }>, index: number): GlslFunction {
  const checked = checkedFormula(seed.formula, SOLID_NAMES);
  if (checked instanceof FormulaError) throw new Error(`seed solid ${seed.nodeId}: ${checked.message}`);
  const body = formulaGlsl(checked.tree, SOLID_GLSL_NAMES);
  const name = `seedSolid${index}`;
  return glslFunction(
    name,
    `
float ${name}(vec3 p, vec4 a, vec4 k) {
  vec3 u = p - a.xyz;
  float len = length(u);
  float ball = len - a.w;
  vec3 q = ball < 0.0 ? u : u * (a.w / max(len, 1e-30));
  float f = (${body.expr}) / k.w;
  return ball < 0.0 ? (isnan(f) ? 0.0 : max(f, ball)) : (isnan(f) ? ball : max(ball, f - ball));
}`,
    body.deps,
  );
}

/**
 * The GLSL call giving seed `index`'s distance at `p` from its packed rows (the functions:
 * seedGlslFunctions): chosen by the seed's kind when the program is generated (the kind is part of
 * the scene's structure, so a sphere never pays for the box's formula, and no function branches on
 * a packed kind flag).
 */
export const seedDistanceCall = (seed: Seed3d, index: number, rows: readonly string[]): string =>
  seed.kind === 'sphere'
    ? `sphereSeedDistance(p, ${rows[0]})`
    : `${seed.kind === 'tile' ? 'tileDistance' : seed.kind === 'formula' ? `seedSolid${index}` : 'boxSeedDistance'}(p, ${rows.join(', ')})`;

/*
 * Why every seed function below has one exit and chooses with `?:` instead of `if … return`:
 * SwiftShader (WebGL without a GPU) inlines these functions into every call site, and its compile
 * time grew about fivefold with each further call of a function with an early return — the
 * Fig. 37 scene (nine seeds) did not finish compiling in minutes, the same scene written with
 * selects compiles in 0.1 s (docs/math-3d.md "Mirror material"; `npm run bench`, "First draw",
 * times every example). The two sides of a select are cheap here.
 */

/** GLSL `sphereSeedDistance(p, a)`: |p − c| − r over the sphere's row (c, r). */
export const sphereSeedGlsl = glslFunction(
  'sphereSeedDistance',
  `
float sphereSeedDistance(vec3 p, vec4 a) {
  return length(p - a.xyz) - a.w;
}`,
);

/** GLSL `boxSeedDistance(p, a, b)`: the exact box distance over its rows (c, 0), (h, 1). */
export const boxSeedGlsl = glslFunction(
  'boxSeedDistance',
  `
float boxSeedDistance(vec3 p, vec4 a, vec4 b) {
  vec3 q = abs(p - a.xyz) - b.xyz;
  return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
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
  float r2 = inv.w * inv.w;
  vec3 v = p - inv.xyz;
  float far = inv.w > 0.0 ? max(dot(v, v), 1e-24) : 1.0;
  vec3 q = inv.w > 0.0 ? inv.xyz + (r2 / far) * v : p;
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
  float f = sqrt(far);
  return inv.w > 0.0 ? f * d / (r2 / f + max(d, 0.0)) : d;
}`,
);

/** The GLSL functions the seeds' distance calls need. */
export const seedGlslFunctions = (seeds: readonly Seed3d[]): GlslFunction[] => [
  ...(seeds.some((s) => s.kind === 'sphere') ? [sphereSeedGlsl] : []),
  ...(seeds.some((s) => s.kind === 'box') ? [boxSeedGlsl] : []),
  ...(seeds.some((s) => s.kind === 'tile') ? [tileDistanceGlsl] : []),
  ...seeds.flatMap((s, k) => (s.kind === 'formula' ? [solidGlsl(s, k)] : [])),
];
