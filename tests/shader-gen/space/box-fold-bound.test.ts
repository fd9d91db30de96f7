/**
 * The tracer's bound with a box fold (docs/math-3d.md §10): a box fold and a sphere inversion, a
 * seed ball in box minus ball. When the ball lies inside the box the group is discrete and the
 * bound never exceeds the brute-force distance to the orbit spheres of words ≤ 5 in the six face
 * reflections and the inversion (it fails with the box's end cover skipped everywhere, i.e. the
 * mirrored cover's L without the box, and with 2·w.de). When the ball crosses the faces (the
 * pseudo-Kleinian proper) the bound is measured: probes inside the ball of radius DE, with the
 * IIS's own hit test, find the drawn orbit no nearer than the recorded fraction of DE.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import type { Sphere } from '../../../nodes/geometry/space/sphere.ts';
import { add3, dist3, scale3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { type Walk3dResult, walk3d } from '../../../shader-gen/space/walk.ts';
import { real, SEED, unit3 } from '../../nodes/geometry/space/arbitraries.ts';
import { bruteDistance, type Involution, involutionOrbit } from './orbit-brute-force.ts';
import { orbitWithin } from './orbit-probe.ts';
import { scene3d, seedSphere } from './scenes-3d.ts';

/** The bound under test: swap in 2·w.de to see the brute-force property fail. */
const boundOf = (w: Walk3dResult): number => w.de;

const AXES: readonly Vec3[] = [
  [1, 0, 0],
  [0, 1, 0],
  [0, 0, 1],
];

/** The six faces of the box (c, h) as plane mirrors (the fold's group). */
const faces = (c: Vec3, h: Vec3): Involution[] =>
  AXES.flatMap((e, k) =>
    [1, -1].map((s) => ({
      plane: { point: add3(c, scale3(e, s * h[k]!)), normal: scale3(e, -s) },
    })),
  );

/**
 * A box (centre 0, half sizes h), the inversion sphere at its centre (radius `rf`·min h) and a seed
 * ball in one corner of box minus ball, with the point around the ball, the seed, or the seed's
 * image in a neighbouring box.
 */
const setup = (rf: fc.Arbitrary<number>) =>
  fc.record({
    h: fc.tuple(real(0.8, 1.5), real(0.8, 1.5), real(0.8, 1.5)) as fc.Arbitrary<Vec3>,
    rf,
    corner: fc.tuple(fc.boolean(), fc.boolean(), fc.boolean()),
    sr: real(0.05, 0.3),
    inset: real(0, 0.2),
    at: fc.integer({ min: 0, max: 2 }),
    dir: unit3,
    t: real(0, 1.6),
  });

type Case = typeof setup extends (rf: fc.Arbitrary<number>) => fc.Arbitrary<infer T> ? T : never;

function caseOf({ h, rf, corner, sr, inset, at, dir, t }: Case) {
  const mirror: Sphere = { center: [0, 0, 0], radius: rf * Math.min(...h) };
  const centre = h.map((hk, k) => (corner[k] ? 1 : -1) * (hk - sr - inset)) as unknown as Vec3;
  const ball: Sphere = { center: centre, radius: sr };
  const clear = dist3(centre, mirror.center) - sr > mirror.radius + 0.01;
  const elements: Element3d[] = [
    { kind: 'box-fold', box: { center: [0, 0, 0], halfSize: h } },
    { kind: 'sphere-inversion', sphere: mirror },
  ];
  const scene = scene3d(elements, [seedSphere(centre, sr)], { maxIterations: 60 });
  const beyond: Sphere = { center: add3(centre, [2 * h[0] * (corner[0] ? 1 : -1), 0, 0]), radius: sr };
  const around = [mirror, ball, beyond][at]!;
  return { scene, mirror, ball, clear, x: add3(around.center, scale3(dir, t * around.radius)) };
}

describe('the tracer bound with a box fold (docs/math-3d.md §10)', () => {
  it('never exceeds the distance to the orbit spheres of words ≤ 5 (ball inside the box: discrete)', () => {
    let runs = 0;
    let deep = 0;
    fc.assert(
      fc.property(setup(real(0.4, 0.95)), (c) => {
        const k = caseOf(c);
        fc.pre(k.clear);
        const w = walk3d(prepareTrace3d(k.scene), ...k.x, true);
        runs++;
        if (w.depth >= 1) deep++;
        const involutions = [...faces([0, 0, 0], c.h), { sphere: k.mirror }];
        const brute = bruteDistance(involutionOrbit(involutions, [k.ball], 5), k.x);
        expect(boundOf(w)).toBeGreaterThanOrEqual(0);
        expect(boundOf(w)).toBeLessThanOrEqual(brute * (1 + 1e-9) + 1e-12);
      }),
      { ...SEED, numRuns: 120 },
    );
    expect(deep).toBeGreaterThan(runs * 0.4);
  }, 120_000);

  it('measured where the ball crosses the faces (pseudo-Kleinian): no drawn orbit inside the bound', () => {
    const found: number[] = [];
    for (const c of fc.sample(setup(real(1.05, 1.4)), { seed: SEED.seed, numRuns: 80 })) {
      const k = caseOf(c);
      if (!k.clear) continue;
      const { de } = walk3d(prepareTrace3d(k.scene), ...k.x, true);
      expect(de).toBeGreaterThanOrEqual(0);
      if (!(de > 1e-9)) continue;
      found.push(orbitWithin(k.scene, k.x, de));
    }
    found.sort((a, b) => a - b);
    console.log(`pseudo-Kleinian: ${found.length} points, orbit first met at ${found.join(' ')} × DE`);
    expect(found.length).toBeGreaterThan(20);
    expect(found[0]).toBeGreaterThan(0.99);
    // The probes do meet the orbit a few bounds away, so a bound a few times too large would fail.
    expect(found.filter((f) => f <= 10).length).toBeGreaterThan(found.length / 2);
  }, 300_000);
});
