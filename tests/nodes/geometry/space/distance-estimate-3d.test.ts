import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { orbitDistanceEstimate, orbitScene } from '../../../../nodes/geometry/space/distance-estimate-3d.ts';
import { iis3d } from '../../../../nodes/geometry/space/iis-3d.ts';
import { invertSphere, type Sphere } from '../../../../nodes/geometry/space/sphere.ts';
import { add3, dist3, scale3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { point3, real, SEED, unit3 } from './arbitraries.ts';

/** Fig. 11-like: six inversion spheres at ±a·e_k (jittered) around a seed sphere at the origin. */
const fig11 = fc
  .record({
    a: real(1.5, 2.5),
    rf: real(0.3, 0.68),
    sf: real(0.2, 0.9),
    jitter: fc.array(point3, { minLength: 6, maxLength: 6 }),
  })
  .map(({ a, rf, sf, jitter }) => {
    const r = rf * a;
    const axes: Vec3[] = [
      [1, 0, 0],
      [-1, 0, 0],
      [0, 1, 0],
      [0, -1, 0],
      [0, 0, 1],
      [0, 0, -1],
    ];
    const mirrors = axes.map((e, i) => ({ center: add3(scale3(e, a), scale3(jitter[i]!, 0.02)), radius: r }));
    return { mirrors, seeds: [{ center: [0, 0, 0] as Vec3, radius: sf * (a - r) * 0.95 }] };
  });

/** All orbit spheres w(seed) for reduced words w of length ≤ maxLength. */
function orbitSpheres(mirrors: readonly Sphere[], seeds: readonly Sphere[], maxLength: number): Sphere[] {
  const all: Sphere[] = [...seeds];
  let level = seeds.map((s) => ({ s, last: -1 }));
  for (let k = 0; k < maxLength; k++) {
    const next: { s: Sphere; last: number }[] = [];
    for (const { s, last } of level) {
      mirrors.forEach((m, i) => {
        if (i === last) return;
        const img = invertSphere(m, s);
        if (img.kind === 'sphere') next.push({ s: img.sphere, last: i });
      });
    }
    all.push(...next.map((n) => n.s));
    level = next;
  }
  return all;
}
const bruteDistance = (spheres: readonly Sphere[], x: Vec3): number =>
  Math.min(...spheres.map((s) => Math.max(0, dist3(x, s.center) - s.radius)));

const sample = fc.record({
  scene: fig11,
  mirror: fc.integer({ min: 0, max: 5 }),
  dir: unit3,
  t: real(0, 1.6),
});

describe('orbitDistanceEstimate (docs/math-3d.md §5)', () => {
  it('never exceeds the distance to the orbit spheres of words up to length 5 (Fig. 11 set-ups)', () => {
    fc.assert(
      fc.property(sample, ({ scene: { mirrors, seeds }, mirror, dir, t }) => {
        const sc = orbitScene(mirrors, seeds);
        fc.pre(sc.ok); // jitter may make two inversion spheres touch
        if (!sc.ok) return;
        const m = mirrors[mirror]!;
        const x = add3(m.center, scale3(dir, t * m.radius));
        const de = orbitDistanceEstimate(sc.value, x, 30);
        const brute = bruteDistance(orbitSpheres(mirrors, seeds, 5), x);
        expect(de).toBeGreaterThanOrEqual(0);
        expect(de).toBeLessThanOrEqual(brute * (1 + 1e-9) + 1e-12);
      }),
      { ...SEED, numRuns: 150 },
    );
  });

  it('is within a small factor of the brute-force distance, where the plain estimate overshoots', () => {
    const ratios: number[] = [];
    let plainOvershoots = 0;
    for (const { scene, mirror, dir, t } of fc.sample(sample, { seed: 7, numRuns: 150 })) {
      const sc = orbitScene(scene.mirrors, scene.seeds);
      if (!sc.ok) continue;
      const m = scene.mirrors[mirror]!;
      const x = add3(m.center, scale3(dir, t * m.radius));
      const brute = bruteDistance(orbitSpheres(scene.mirrors, scene.seeds, 4), x);
      if (brute < 1e-6) continue;
      ratios.push(orbitDistanceEstimate(sc.value, x, 30) / brute);
      const r = iis3d(
        scene.mirrors.map((sphere) => ({ kind: 'sphere-inversion' as const, sphere })),
        x,
        30,
      );
      const s = scene.seeds[0]!;
      if ((dist3(r.point, s.center) - s.radius) / r.factor > brute * 1.01) plainOvershoots++;
    }
    ratios.sort((a, b) => a - b);
    expect(plainOvershoots).toBeGreaterThan(0);
    expect(ratios[Math.floor(ratios.length / 2)]).toBeGreaterThan(0.5); // measured: median 0.70, min 0.32
  });

  it('rejects overlapping inversion spheres and seeds that meet them', () => {
    const m: Sphere = { center: [0, 0, 0], radius: 1 };
    expect(orbitScene([m, { center: [1.5, 0, 0], radius: 1 }], []).ok).toBe(false);
    expect(orbitScene([m], [{ center: [1.2, 0, 0], radius: 0.5 }]).ok).toBe(false);
  });
});
