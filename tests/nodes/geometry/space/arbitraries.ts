/** Shared fast-check arbitraries for the 3-D geometry tests: points, spheres, generator set-ups. */
import fc from 'fast-check';
import {
  type CompoundLoxodromic3d,
  compoundLoxodromic3d,
} from '../../../../nodes/geometry/space/compound-loxodromic-3d.ts';
import type { Sphere } from '../../../../nodes/geometry/space/sphere.ts';
import { add3, normalize3, scale3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';

export const SEED = { seed: 20261125, numRuns: 200 } as const;
/** Uniform reals in [min, max]: fc.double draws uniformly over bit patterns (mostly tiny values), which makes degenerate set-ups. */
export const real = (min: number, max: number): fc.Arbitrary<number> =>
  fc.noBias(fc.integer({ min: 0, max: 1 << 30 })).map((i) => min + ((max - min) * i) / (1 << 30));
export const coord = real(-4, 4);
export const point3 = fc.tuple(coord, coord, coord) as fc.Arbitrary<Vec3>;
export const radius = real(0.2, 3);
export const sphere = fc.record({ center: point3, radius }) as fc.Arbitrary<Sphere>;
/** A unit vector (rejecting the near-zero draws). */
export const unit3 = point3.filter((v) => Math.hypot(...v) > 0.1).map(normalize3);

/** Nested set-up: c2 inside S1 and S1 inside S2 (paper Fig. 19). */
export const nestedPair = fc
  .record({
    c2: point3,
    r1: real(0.3, 1.5),
    f: real(0, 0.8),
    dir: unit3,
    margin: real(0.1, 2),
  })
  .map(({ c2, r1, f, dir, margin }) => {
    const off = scale3(dir, f * r1);
    const s1: Sphere = { center: add3(c2, off), radius: r1 };
    const s2: Sphere = { center: c2, radius: f * r1 + r1 + margin };
    return { s1, s2 };
  });

/** Disjoint set-up: the balls of S1 and S2 are apart (classical Schottky pairing). */
export const disjointPair = fc
  .record({ s1: sphere, r2: radius, dir: unit3, gap: real(0.05, 3) })
  .map(({ s1, r2, dir, gap }) => ({
    s1,
    s2: { center: add3(s1.center, scale3(dir, s1.radius + r2 + gap)), radius: r2 } as Sphere,
  }));

/** A nested S1, S2 with control points P, Q1, Q2 whose spheres S3, S4 are well conditioned. */
export const compoundSetup = fc
  .tuple(nestedPair, point3, point3, point3)
  .map(([{ s1, s2 }, p, q1, q2]) => compoundLoxodromic3d(s1, s2, p, q1, q2))
  .filter((r) => r.ok && r.value.s3.radius < 100 && r.value.s4.radius < 100)
  .map((r) => (r as { ok: true; value: CompoundLoxodromic3d }).value);
