/**
 * The tracer's distance bound (docs/math-3d.md "§8 The tracer's distance bound") is safe: on random configurations it never
 * exceeds the brute-force distance to the enumerated orbit spheres — Fig. 11-like inversion scenes
 * (content balls and reaches) and two-sphere generators (the conservative fallback) — while the
 * plain estimate seedDistance(final)/factor does overshoot on the same points — and on cube-type
 * sphairahedra (overlapping mirrors, clipped seeds, planes) no orbit point lies in the ball it
 * claims empty.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Element3d, Seed3d } from '../../../nodes/core/scene-3d.ts';
import { sampleSpace } from '../../../nodes/core/seed-3d.ts';
import { mobius3d } from '../../../nodes/geometry/space/mobius-3d.ts';
import {
  CUBE_TYPES,
  defaultInversionSphere,
  finiteElements,
  finiteSphairahedron,
  infiniteElements,
  infiniteSeedBox,
  infiniteSphairahedron,
} from '../../../nodes/geometry/space/sphairahedron.ts';
import type { Sphere } from '../../../nodes/geometry/space/sphere.ts';
import { add3, scale3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { walk3d } from '../../../shader-gen/space/walk.ts';
import { point3, real, SEED, unit3 } from '../../nodes/geometry/space/arbitraries.ts';
import { bruteDistance, generatorOrbit, inversionOrbit } from './orbit-brute-force.ts';
import { scene3d, seedSphere } from './scenes-3d.ts';

const AXES: readonly Vec3[] = [
  [1, 0, 0],
  [-1, 0, 0],
  [0, 1, 0],
  [0, -1, 0],
  [0, 0, 1],
  [0, 0, -1],
];

/** Six inversion spheres at ±a·e_k (jittered, random radius) around one seed sphere at the origin. */
const fig11 = fc
  .record({
    a: real(1.5, 2.5),
    rf: real(0.3, 0.68),
    sf: real(0.2, 0.9),
    jitter: fc.array(point3, { minLength: 6, maxLength: 6 }),
  })
  .map(({ a, rf, sf, jitter }) => {
    const r = rf * a;
    const mirrors = AXES.map((e, i) => ({ center: add3(scale3(e, a), scale3(jitter[i]!, 0.02)), radius: r }));
    return { mirrors, seeds: [{ center: [0, 0, 0] as Vec3, radius: sf * (a - r) * 0.95 }] };
  });

const sample = fc.record({
  scene: fig11,
  mirror: fc.integer({ min: 0, max: 5 }),
  dir: unit3,
  t: real(0, 1.6),
});

function sceneOf(mirrors: readonly Sphere[], seeds: readonly Sphere[]) {
  const elements: Element3d[] = mirrors.map((sphere) => ({ kind: 'sphere-inversion', sphere }));
  return prepareTrace3d(
    scene3d(
      elements,
      seeds.map((s) => seedSphere(s.center, s.radius)),
    ),
  );
}

describe('the tracer bound (docs/math-3d.md §8)', () => {
  it('never exceeds the distance to the orbit spheres of words ≤ 5 (Fig. 11 set-ups)', () => {
    fc.assert(
      fc.property(sample, ({ scene: { mirrors, seeds }, mirror, dir, t }) => {
        const m = mirrors[mirror]!;
        const x = add3(m.center, scale3(dir, t * m.radius));
        const plan = sceneOf(mirrors, seeds);
        const { de } = walk3d(plan, ...x, true);
        const brute = bruteDistance(inversionOrbit(mirrors, seeds, 5), x);
        expect(de).toBeGreaterThanOrEqual(0);
        expect(de).toBeLessThanOrEqual(brute * (1 + 1e-9) + 1e-12);
      }),
      { ...SEED, numRuns: 150 },
    );
  }, 120_000);

  it('is within a small factor of the brute-force distance where the plain estimate overshoots', () => {
    const ratios: number[] = [];
    let overshoots = 0;
    for (const { scene, mirror, dir, t } of fc.sample(sample, { seed: 7, numRuns: 150 })) {
      const m = scene.mirrors[mirror]!;
      const x = add3(m.center, scale3(dir, t * m.radius));
      const brute = bruteDistance(inversionOrbit(scene.mirrors, scene.seeds, 4), x);
      if (brute < 1e-6) continue;
      const w = walk3d(sceneOf(scene.mirrors, scene.seeds), ...x, true);
      ratios.push(w.de / brute);
      if (w.imageDistance > brute * 1.01) overshoots++;
    }
    ratios.sort((a, b) => a - b);
    expect(overshoots).toBeGreaterThan(0);
    // Measured (seed 7): median 0.77, lowest 0.20; the plain estimate overshoots on 114 of 150.
    expect(ratios[Math.floor(ratios.length / 2)]).toBeGreaterThan(0.5);
  }, 120_000);

  /** A hyperbolic two-sphere generator (disjoint spheres) with a seed in its fundamental domain. */
  const generator = fc
    .record({
      d: real(2.2, 4),
      r1: real(0.4, 1),
      r2: real(0.4, 1),
      seed: point3,
      sr: real(0.05, 0.5),
      dir: unit3,
      t: real(0, 1.5),
      at: fc.integer({ min: 0, max: 2 }),
    })
    .map(({ d, r1, r2, seed, sr, dir, t, at }) => ({
      s1: { center: [-d / 2, 0, 0] as Vec3, radius: r1 },
      s2: { center: [d / 2, 0, 0] as Vec3, radius: r2 },
      seed: { center: scale3(seed, 0.3), radius: sr },
      dir,
      t,
      at,
    }));

  it('never exceeds the orbit distance for a two-sphere generator (the fallback, |k| ≤ 6)', () => {
    fc.assert(
      fc.property(generator, ({ s1, s2, seed, dir, t, at }) => {
        const g = mobius3d(s1, s2);
        if (!g.ok) return;
        const plan = prepareTrace3d(
          scene3d([{ kind: 'mobius-3d', g: g.value }], [seedSphere(seed.center, seed.radius)]),
        );
        // The seed must lie in the fundamental domain (outside A and B).
        const clear = (b: { sphere: Sphere; inside: boolean }) => {
          const dc = Math.hypot(
            ...(b.sphere.center.map((c, k) => c - seed.center[k]!) as [number, number, number]),
          );
          return b.inside ? dc > b.sphere.radius + seed.radius : dc + seed.radius < b.sphere.radius;
        };
        fc.pre(clear(g.value.a) && clear(g.value.b));
        const around = [g.value.a.sphere, g.value.b.sphere, seed][at]!;
        const x = add3(around.center, scale3(dir, t * around.radius));
        const { de } = walk3d(plan, ...x, true);
        const brute = bruteDistance(generatorOrbit(s1, s2, [seed], 6), x);
        expect(de).toBeGreaterThanOrEqual(0);
        expect(de).toBeLessThanOrEqual(brute * (1 + 1e-9) + 1e-12);
      }),
      { ...SEED, numRuns: 150 },
    );
  });

  /**
   * A cube-type sphairahedron (Figs. 26–28): finite (six overlapping inversion spheres, the seed
   * ball reaching into them) or infinite (three planes, three spheres, a box seed), and a point
   * around one of its sphere faces.
   */
  const sphairahedron = fc.record({
    type: fc.constantFrom(...CUBE_TYPES),
    zb: real(-0.3, 0.3),
    zc: real(-0.3, 0.3),
    finite: fc.boolean(),
    lift: real(0, 1),
    radius: real(1, 2),
    face: fc.integer({ min: 0, max: 2 }),
    dir: unit3,
    t: real(0, 1.6),
  });

  type SphairahedronSample = typeof sphairahedron extends fc.Arbitrary<infer T> ? T : never;

  /** The scene and point of a sphairahedron sample, or null when the shape is refused. */
  function sphairahedronCase(c: SphairahedronSample) {
    const inf = infiniteSphairahedron(c.type, c.zb, c.zc);
    if (!inf.ok) return null;
    const color: Vec3 = [0.8, 0.7, 0.4];
    let elements: Element3d[] = infiniteElements(inf.value);
    const box = infiniteSeedBox(inf.value);
    let seed: Seed3d = { kind: 'box', nodeId: 's', ...box, color, clipped: true };
    let face = inf.value.spheres[c.face]!;
    if (c.finite) {
      const inv = defaultInversionSphere(inf.value);
      const at: Vec3 = [inv.center[0], inv.center[1], inv.center[2] + c.lift];
      const fin = finiteSphairahedron(inf.value, { center: at, radius: c.radius });
      if (!fin.ok) return null;
      elements = finiteElements(fin.value);
      seed = { kind: 'sphere', nodeId: 's', sphere: fin.value.seed, color, clipped: true };
      face = fin.value.spheres[3 + c.face]!;
    }
    const scene = scene3d(elements, [seed], { maxIterations: 40 });
    return { scene, x: add3(face.center, scale3(c.dir, c.t * face.radius)) };
  }

  /** Directions for probing a ball: a fixed, well-spread set (golden-spiral points). */
  const PROBES: Vec3[] = Array.from({ length: 400 }, (_, k) => {
    const z = 1 - (2 * (k + 0.5)) / 400;
    const a = k * Math.PI * (3 - Math.sqrt(5));
    const h = Math.sqrt(1 - z * z);
    return [h * Math.cos(a), h * Math.sin(a), z];
  });

  /** Shell radii, as fractions of the bound: inside it up to 0.99, then beyond it up to 10. */
  const SHELLS = [0.1, 0.25, 0.4, 0.55, 0.7, 0.85, 0.99, 1.5, 2, 3, 4, 6, 8, 10];

  /** The smallest shell radius ρ (× de) whose probe points meet the orbit, else ∞. */
  function orbitWithin(scene: ReturnType<typeof scene3d>, x: Vec3, de: number): number {
    const deep = { ...scene, maxIterations: 200 };
    for (const rho of SHELLS) {
      for (const p of PROBES) {
        const s = sampleSpace(deep, add3(x, scale3(p, rho * de)));
        if (s.escaped && s.distance !== null && s.distance < 0) return rho;
      }
    }
    return Number.POSITIVE_INFINITY;
  }

  it('leaves no orbit point in the ball it claims empty (cube-type sphairahedra, finite and infinite)', () => {
    let tested = 0;
    let nearby = 0;
    for (const c of fc.sample(sphairahedron, { seed: SEED.seed, numRuns: 60 })) {
      const k = sphairahedronCase(c);
      if (!k) continue;
      const { de } = walk3d(prepareTrace3d(k.scene), ...k.x, true);
      expect(de).toBeGreaterThanOrEqual(0);
      if (!(de > 1e-9)) continue;
      tested++;
      const found = orbitWithin(k.scene, k.x, de);
      expect(found).toBeGreaterThan(0.99);
      if (found <= 10) nearby++;
    }
    expect(tested).toBeGreaterThan(25);
    // The probes do find the orbit a few bounds away for most points, so a bound a few times too
    // large would fail. Measured (this seed): 39 points; the orbit first met at 3–10 bounds for 29
    // of them (median 6), not within 10 for the other 10.
    expect(nearby).toBeGreaterThan(tested / 2);
  }, 300_000);
});
