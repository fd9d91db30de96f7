/**
 * Facts about a 3D orbit seed that the nodes, the CLI and tests share: its signed distance and the
 * points that stand for it when checking where it lies (docs/math-3d.md §7).
 */
import { solidSeedDistance } from '../formula/solid.ts';
import { boxSignedDistance } from '../geometry/space/box.ts';
import { type Iis3dResult, iis3d } from '../geometry/space/iis-3d.ts';
import { tileSignedDistance } from '../geometry/space/sphairahedron-tile.ts';
import { add3, dist3, scale3 } from '../geometry/space/vec3.ts';
import type { Scene3d, Seed3d, Vec3 } from './scene-3d.ts';

/**
 * Signed distance from x to the seed's surface (negative inside): |x − c| − r for a sphere, a box's
 * own; a solid's formula bound (nodes/formula/solid.ts, a lower bound of the distance outside).
 */
export function seedSignedDistance(seed: Seed3d, x: Vec3): number {
  if (seed.kind === 'sphere') return dist3(x, seed.sphere.center) - seed.sphere.radius;
  if (seed.kind === 'formula') return solidSeedDistance(seed, x[0], x[1], x[2]);
  if (seed.kind === 'tile') return tileSignedDistance(seed.tile, x[0], x[1], x[2]);
  return boxSignedDistance(seed.center, seed.halfSize, x);
}

const AXES: readonly Vec3[] = [
  [1, 0, 0],
  [-1, 0, 0],
  [0, 1, 0],
  [0, -1, 0],
  [0, 0, 1],
  [0, 0, -1],
];

/**
 * Points that stand for a seed: its centre and its extreme points (a sphere's six axis points, a
 * box's eight corners, a solid's bounding ball's six). A seed lies in the fundamental domain when no element moves any of them.
 */
export function seedSamplePoints(seed: Seed3d): Vec3[] {
  // A tile is the fundamental domain itself (render-3d does not check it: it is `clipped`).
  if (seed.kind === 'tile') return [];
  if (seed.kind !== 'box') {
    // A solid stands for its bounding ball: what the ball's points avoid, the solid avoids.
    const { center, radius } = seed.kind === 'sphere' ? seed.sphere : seed;
    return [center, ...AXES.map((a) => add3(center, scale3(a, radius)))];
  }
  const corners: Vec3[] = [];
  const [hx, hy, hz] = seed.halfSize;
  for (const sx of [-hx, hx])
    for (const sy of [-hy, hy]) for (const sz of [-hz, hz]) corners.push(add3(seed.center, [sx, sy, sz]));
  return [seed.center, ...corners];
}

/** The IIS at one point of space and the distance to the seeds' orbit estimated from it. */
export interface SpaceSample extends Iis3dResult {
  /** min over seeds of d_seed(final point) / factor (signed, negative inside); null without seeds. */
  readonly distance: number | null;
}

/**
 * Runs the IIS from p (docs/math-3d.md §4) and estimates the signed distance from p to the nearest
 * seed image: the seed's distance at the final point, divided by the accumulated conformal factor
 * (which turns lengths near the final point back into lengths near p). This is the plain estimate
 * of docs/math-3d.md §5: exact in sign at p, not a safe bound for marching.
 */
export function sampleSpace(
  scene: Pick<Scene3d, 'elements' | 'seeds' | 'maxIterations'>,
  p: Vec3,
): SpaceSample {
  const r = iis3d(scene.elements, p, scene.maxIterations);
  if (scene.seeds.length === 0) return { ...r, distance: null };
  let d = Number.POSITIVE_INFINITY;
  for (const seed of scene.seeds) d = Math.min(d, seedSignedDistance(seed, r.point));
  return { ...r, distance: d / r.factor };
}
