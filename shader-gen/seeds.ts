/**
 * Orbit seeds on the CPU (docs/math.md "orbit seeds"): which seed, if any, holds a point, and the
 * linear colour it paints there. glsl/seeds.glsl.ts is the twin: seedAt is emitted straight-line,
 * one block per seed, with the same tests.
 */
import type { SeedSpec } from '../nodes/core/scene.ts';
import { checkedFormula } from '../nodes/formula/checked.ts';
import type { FormulaValue } from '../nodes/formula/functions.ts';
import { SHAPE_NAMES } from '../nodes/formula/names.ts';
import { type PictureMap, resolvePicture, samplePicture } from './picture.ts';
import { placeUv, rotationPair } from './placement.ts';
import { type Rgb, toLinear } from './srgb.ts';

/** Disk seed: |p − c|² < r² (strict, like every inside test). */
export const seedDiskInside = (c: readonly [number, number], r: number, x: number, y: number): boolean =>
  (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) < r * r;

/** Image seed: the picture-local point lies strictly inside the rectangle (0 < u < 1, 0 < v < 1). */
function seedImageUv(seed: Extract<SeedSpec, { kind: 'image' }>, x: number, y: number): [number, number] {
  const [cos, sin] = rotationPair(seed.rotation);
  return placeUv(seed.center[0], seed.center[1], seed.width, seed.height, cos, sin, x, y);
}

/** Each seed's checked formula, looked up once per seed rather than by its text at every step. */
const shapeFormulas = new WeakMap<object, ReturnType<typeof checkedFormula>>();
const shapeEnv = { a: 0, b: 0, c: 0, t: 0, x: 0, y: 0, p: [0, 0], q: [0, 0], z: [0, 0] };
const setPoint = (v: number[], x: number, y: number) => {
  v[0] = x;
  v[1] = y;
};

/**
 * A shape seed's formula at z = (x, y) (docs/formula.md "Seed shapes"): negative inside. A formula
 * that does not check (the node reports it, so it never reaches a scene) is +∞: it holds nothing.
 */
export function seedShapeValue(seed: Extract<SeedSpec, { kind: 'shape' }>, x: number, y: number): number {
  let f = shapeFormulas.get(seed);
  if (!f) {
    f = checkedFormula(seed.formula, SHAPE_NAMES);
    shapeFormulas.set(seed, f);
  }
  if (!('run' in f)) return Number.POSITIVE_INFINITY;
  const [a, b, c, t] = seed.numbers;
  const [px, py, qx, qy] = seed.points;
  // One scratch environment, refilled (the CPU renderer is single-threaded per worker).
  const env = shapeEnv;
  env.a = a;
  env.b = b;
  env.c = c;
  env.t = t;
  env.x = x;
  env.y = y;
  setPoint(env.p, px, py);
  setPoint(env.q, qx, qy);
  setPoint(env.z, x, y);
  return f.run(env as unknown as Record<string, FormulaValue>) as number;
}

/** Index of the first seed (in order) holding (x, y), or −1. */
export function seedAt(seeds: readonly SeedSpec[], x: number, y: number): number {
  for (let i = 0; i < seeds.length; i++) {
    const seed = seeds[i];
    if (seed.kind === 'disk') {
      if (seedDiskInside(seed.c, seed.r, x, y)) return i;
    } else if (seed.kind === 'shape') {
      if (seedShapeValue(seed, x, y) < 0) return i;
    } else {
      const [u, v] = seedImageUv(seed, x, y);
      if (u > 0 && u < 1 && v > 0 && v < 1) return i;
    }
  }
  return -1;
}

/** Linear colour a seed paints at (x, y): its colour, or its picture's texel there. */
export function seedColour(seed: SeedSpec, x: number, y: number, pictures: PictureMap | undefined): Rgb {
  if (seed.kind !== 'image') return toLinear(seed.color);
  const [u, v] = seedImageUv(seed, x, y);
  return samplePicture(resolvePicture(seed.image.src, pictures), u, v);
}
