/**
 * Orbit seeds on the CPU (docs/math.md "orbit seeds"): which seed, if any, holds a point, and the
 * linear colour it paints there. glsl/seeds.glsl.ts is the twin: seedAt is emitted straight-line,
 * one block per seed, with the same tests.
 */
import type { SeedSpec } from '../nodes/core/scene.ts';
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

/** Index of the first seed (in order) holding (x, y), or −1. */
export function seedAt(seeds: readonly SeedSpec[], x: number, y: number): number {
  for (let i = 0; i < seeds.length; i++) {
    const seed = seeds[i];
    if (seed.kind === 'disk') {
      if (seedDiskInside(seed.c, seed.r, x, y)) return i;
    } else {
      const [u, v] = seedImageUv(seed, x, y);
      if (u > 0 && u < 1 && v > 0 && v < 1) return i;
    }
  }
  return -1;
}

/** Linear colour a seed paints at (x, y): its colour, or its picture's texel there. */
export function seedColour(seed: SeedSpec, x: number, y: number, pictures: PictureMap | undefined): Rgb {
  if (seed.kind === 'disk') return toLinear(seed.color);
  const [u, v] = seedImageUv(seed, x, y);
  return samplePicture(resolvePicture(seed.image.src, pictures), u, v);
}
