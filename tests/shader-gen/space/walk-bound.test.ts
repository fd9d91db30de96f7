/**
 * The tracer's distance bound (docs/math-3d.md "§8 The tracer's distance bound") is safe: on random
 * configurations it never exceeds the brute-force distance to the enumerated orbit spheres (a
 * finite part of the orbit, so never below the true distance) — Fig. 11-like inversion scenes with
 * disjoint mirrors (content balls and reaches) and with tangent mirrors (adjacent spheres touching),
 * two-sphere, compound loxodromic and compound parabolic generators, and a plane mirror with two
 * inversion spheres — while the plain estimate seedDistance(final)/factor does overshoot on the
 * same points; and on cube-type sphairahedra (overlapping mirrors, clipped seeds, planes) no orbit
 * point lies in the ball it claims empty. Each of these properties fails with boundOf swapped for
 * w.imageDistance or for 2·w.de, and each asserts that many of its points are moved by the walk.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Element3d, Seed3d } from '../../../nodes/core/scene-3d.ts';
import { sampleSpace } from '../../../nodes/core/seed-3d.ts';
import { compoundLoxodromic3d } from '../../../nodes/geometry/space/compound-loxodromic-3d.ts';
import {
  applyCompoundParabolic3d,
  applyCompoundParabolic3dInverse,
  compoundParabolic3d,
} from '../../../nodes/geometry/space/compound-parabolic-3d.ts';
import { mobius3d } from '../../../nodes/geometry/space/mobius-3d.ts';
import {
  CUBE_TYPES,
  defaultInversionSphere,
  finiteElements,
  finiteSphairahedron,
  type InfiniteSphairahedron,
  infiniteElements,
  infiniteSeedBox,
  infiniteSphairahedron,
} from '../../../nodes/geometry/space/sphairahedron.ts';
import { spaceClass } from '../../../nodes/geometry/space/sphairahedron-space.ts';
import { sphairahedronTile } from '../../../nodes/geometry/space/sphairahedron-tile.ts';
import type { Sphere } from '../../../nodes/geometry/space/sphere.ts';
import { add3, dist3, dot3, scale3, sub3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { type Walk3dResult, walk3d } from '../../../shader-gen/space/walk.ts';
import { point3, real, SEED, unit3 } from '../../nodes/geometry/space/arbitraries.ts';
import {
  bruteDistance,
  chainOrbit,
  generatorOrbit,
  type Involution,
  inversionOrbit,
  involutionOrbit,
  isometryOrbit,
} from './orbit-brute-force.ts';
import { orbitWithin, PROBES, SHELLS } from './orbit-probe.ts';
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

/** The bound under test: swap in an unsafe estimate (w.imageDistance, 2·w.de) to see the properties fail. */
const boundOf = (w: Walk3dResult): number => w.de;

/** 0 ≤ bound ≤ the brute-force orbit distance, up to rounding. */
function expectSafe(bound: number, brute: number): void {
  expect(bound).toBeGreaterThanOrEqual(0);
  expect(bound).toBeLessThanOrEqual(brute * (1 + 1e-9) + 1e-12);
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
    // Measured (seed 7, the bound formed once at the final point through the pole of W): median
    // 0.67, lowest 0.081; the plain estimate overshoots on 114 of 150.
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

  /** Whether a seed ball lies clear of a region (a ball side) with a margin. */
  const clearOf = (seed: Sphere, side: { sphere: Sphere; inside: boolean }, margin = 0.01): boolean => {
    const dc = dist3(side.sphere.center, seed.center);
    return side.inside
      ? dc > side.sphere.radius + seed.radius + margin
      : dc + seed.radius + margin < side.sphere.radius;
  };

  /**
   * Fig. 11 with tangent neighbours: the six spheres at ±a·e_k have radius a/√2 exactly, so each
   * touches its four neighbours at a(e_i + e_j)/2 (a limit point of the orbit: parabolic words); the
   * seed sits at the origin in the fundamental domain. Points around a mirror or near a tangency point.
   */
  const tangent = fc.record({
    a: real(1.5, 2.5),
    sf: fc.constantFrom(0.2, 0.45, 0.7, 0.9),
    nearTouch: fc.boolean(),
    mirror: fc.integer({ min: 0, max: 5 }),
    other: fc.integer({ min: 0, max: 3 }),
    dir: unit3,
    t: real(0, 1.6),
    u: real(0, 1),
  });

  /** The words ≤ 5 orbit of the tangent set-up for a = 1 (the set-up for a is this one scaled by a), per seed size. */
  const unitTangentOrbits = new Map<number, Sphere[]>();
  const unitTangentOrbit = (sf: number): Sphere[] => {
    let orbit = unitTangentOrbits.get(sf);
    if (!orbit) {
      const r = 1 / Math.SQRT2;
      const mirrors = AXES.map((e) => ({ center: e, radius: r }));
      orbit = inversionOrbit(mirrors, [{ center: [0, 0, 0], radius: sf * (1 - r) * 0.95 }], 5);
      unitTangentOrbits.set(sf, orbit);
    }
    return orbit;
  };

  it('never exceeds the distance to the orbit spheres of words ≤ 5 (tangent mirrors)', () => {
    let runs = 0;
    let deep = 0;
    fc.assert(
      fc.property(tangent, ({ a, sf, nearTouch, mirror, other, dir, t, u }) => {
        const r = a / Math.SQRT2;
        const mirrors: Sphere[] = AXES.map((e) => ({ center: scale3(e, a), radius: r }));
        const seeds: Sphere[] = [{ center: [0, 0, 0], radius: sf * (a - r) * 0.95 }];
        // The four axes not opposite to `mirror` (AXES pairs ±e_k at 2k, 2k + 1).
        const j = [0, 1, 2, 3, 4, 5].filter((k) => k >> 1 !== mirror >> 1)[other]!;
        const touch = scale3(add3(AXES[mirror]!, AXES[j]!), a / 2);
        const x = nearTouch
          ? add3(touch, scale3(dir, u * u * 0.4 * r))
          : add3(mirrors[mirror]!.center, scale3(dir, t * r));
        const w = walk3d(sceneOf(mirrors, seeds), ...x, true);
        runs++;
        if (w.depth >= 1) deep++;
        expectSafe(boundOf(w), a * bruteDistance(unitTangentOrbit(sf), scale3(x, 1 / a)));
      }),
      { ...SEED, numRuns: 150 },
    );
    expect(deep).toBeGreaterThan(runs * 0.4);
  }, 120_000);

  /**
   * A compound loxodromic generator G = (I_S4∘I_S3)∘(I_S2∘I_S1) on two disjoint spheres (Fig. 20's
   * kind of set-up: S1, S2 on the x axis, P off the axis, Q1, Q2 anywhere) with a seed ball in its
   * fundamental domain (outside A = ball S1 and B = ball S1′), and a point around S1, S1′, S2 or the seed.
   */
  const loxodromic = fc.record({
    d: real(2.1, 3),
    r1: real(0.6, 1),
    r2: real(0.6, 1),
    p: fc.tuple(real(-0.5, 0.5), real(-1.5, 1.5), real(-1.5, 1.5)) as fc.Arbitrary<Vec3>,
    q1: fc.tuple(real(-2, 2), real(-2, 2), real(-2, 2)) as fc.Arbitrary<Vec3>,
    q2: fc.tuple(real(-2, 2), real(-2, 2), real(-2, 2)) as fc.Arbitrary<Vec3>,
    seed: fc.tuple(real(-1.5, 1.5), real(-1.5, 1.5), real(-1.5, 1.5)) as fc.Arbitrary<Vec3>,
    sr: real(0.05, 0.5),
    at: fc.integer({ min: 0, max: 3 }),
    dir: unit3,
    t: real(0, 1.3),
  });

  it('never exceeds the orbit distance for a compound loxodromic generator (|k| ≤ 6)', () => {
    let runs = 0;
    let deep = 0;
    fc.assert(
      fc.property(loxodromic, ({ d, r1, r2, p, q1, q2, seed, sr, at, dir, t }) => {
        fc.pre(Math.hypot(p[1], p[2]) > 0.3);
        const s1: Sphere = { center: [-d / 2, 0, 0], radius: r1 };
        const s2: Sphere = { center: [d / 2, 0, 0], radius: r2 };
        const g = compoundLoxodromic3d(s1, s2, p, q1, q2);
        fc.pre(g.ok && g.value.s3.radius < 50 && g.value.s4.radius < 50);
        if (!g.ok) return;
        const ball: Sphere = { center: seed, radius: sr };
        fc.pre(clearOf(ball, g.value.base.a) && clearOf(ball, g.value.base.b));
        const plan = prepareTrace3d(
          scene3d([{ kind: 'compound-loxodromic-3d', g: g.value }], [seedSphere(seed, sr)]),
        );
        const around = [s1, g.value.base.s1Image, s2, ball][at]!;
        const x = add3(around.center, scale3(dir, t * around.radius));
        const w = walk3d(plan, ...x, true);
        runs++;
        if (w.depth >= 1) deep++;
        const orbit = chainOrbit([s1, s2, g.value.s3, g.value.s4], [ball], 6);
        expectSafe(boundOf(w), bruteDistance(orbit, x));
      }),
      { ...SEED, numRuns: 150 },
    );
    expect(deep).toBeGreaterThan(runs * 0.25);
  });

  /**
   * A compound parabolic generator G = R_θ ∘ T (an isometry: translation by 2h·n, then a turn by
   * the torsion about the axis through q along n) with a seed ball inside the slab 0 < (x − q)·n < 2h,
   * and a point near one of the seed's images G^k(seed), |k| ≤ 5.
   */
  const parabolic = fc.record({
    q: point3,
    n: unit3,
    h: real(0.3, 1.5),
    torsion: real(-3, 3),
    s0: real(0.1, 1.9),
    sr: real(0.1, 0.9),
    lateral: point3,
    k: fc.integer({ min: -5, max: 5 }),
    dir: unit3,
    t: real(0, 2.5),
  });

  it('never exceeds the orbit distance for a compound parabolic generator (|k| ≤ 8)', () => {
    let runs = 0;
    let deep = 0;
    fc.assert(
      fc.property(parabolic, ({ q, n, h, torsion, s0, sr, lateral, k, dir, t }) => {
        const g = compoundParabolic3d(scale3(q, 0.5), n, h, torsion);
        if (!g.ok) throw new Error(g.error);
        const G = g.value;
        const side = scale3(lateral, 0.4);
        const off = sub3(side, scale3(G.normal, dot3(side, G.normal)));
        const ball: Sphere = {
          center: add3(add3(G.point, scale3(G.normal, s0 * h)), off),
          radius: sr * h * Math.min(s0, 2 - s0),
        };
        const forward = (p: Vec3) => applyCompoundParabolic3d(G, p).x;
        const backward = (p: Vec3) => applyCompoundParabolic3dInverse(G, p).x;
        let image = ball.center;
        for (let i = 0; i < Math.abs(k); i++) image = (k > 0 ? forward : backward)(image);
        const x = add3(image, scale3(dir, t * h));
        const plan = prepareTrace3d(
          scene3d([{ kind: 'compound-parabolic-3d', g: G }], [seedSphere(ball.center, ball.radius)]),
        );
        const w = walk3d(plan, ...x, true);
        runs++;
        if (w.depth >= 1) deep++;
        expectSafe(boundOf(w), bruteDistance(isometryOrbit(forward, backward, [ball], 8), x));
      }),
      { ...SEED, numRuns: 200 },
    );
    expect(deep).toBeGreaterThan(runs * 0.5);
  });

  /**
   * A mixed scene: the plane z = 0 (reflection; kept side z > 0) and two disjoint inversion spheres
   * clear above it, the elements in either order, a seed ball in the fundamental domain (above the
   * plane, outside both balls), and a point around a sphere, a sphere's mirror image below the plane,
   * the seed or its mirror image.
   */
  const mixed = fc.record({
    r1: real(0.4, 1),
    r2: real(0.4, 1),
    g1: real(0.05, 1),
    g2: real(0.05, 1),
    dx: real(0.5, 3),
    dy: real(-1, 1),
    seed: fc.tuple(real(-2, 2), real(-1.5, 1.5), real(0, 2.5)) as fc.Arbitrary<Vec3>,
    sr: real(0.05, 0.5),
    planeAt: fc.integer({ min: 0, max: 2 }),
    at: fc.integer({ min: 0, max: 4 }),
    dir: unit3,
    t: real(0, 1.6),
  });

  it('never exceeds the distance to the orbit spheres of words ≤ 6 (a plane mirror and two spheres)', () => {
    let runs = 0;
    let deep = 0;
    fc.assert(
      fc.property(mixed, ({ r1, r2, g1, g2, dx, dy, seed, sr, planeAt, at, dir, t }) => {
        const a: Sphere = { center: [-dx / 2, 0, r1 + g1], radius: r1 };
        const b: Sphere = { center: [dx / 2, dy, r2 + g2], radius: r2 };
        const ball: Sphere = { center: seed, radius: sr };
        fc.pre(dist3(a.center, b.center) > r1 + r2 + 0.02);
        fc.pre(seed[2] - sr > 0.01 && clearOf(ball, { sphere: a, inside: true }));
        fc.pre(clearOf(ball, { sphere: b, inside: true }));
        const plane = { point: [0, 0, 0] as Vec3, normal: [0, 0, 1] as Vec3 };
        const involutions: Involution[] = [{ sphere: a }, { sphere: b }];
        involutions.splice(planeAt, 0, { plane });
        const elements: Element3d[] = involutions.map((m) =>
          'plane' in m
            ? { kind: 'plane-reflection', plane: m.plane }
            : { kind: 'sphere-inversion', sphere: m.sphere },
        );
        const plan = prepareTrace3d(scene3d(elements, [seedSphere(seed, sr)]));
        const below = (s: Sphere): Sphere => ({
          center: [s.center[0], s.center[1], -s.center[2]],
          radius: s.radius,
        });
        const around = [a, b, below(a), below(ball), ball][at]!;
        const x = add3(around.center, scale3(dir, t * around.radius));
        const w = walk3d(plan, ...x, true);
        runs++;
        if (w.depth >= 1) deep++;
        expectSafe(boundOf(w), bruteDistance(involutionOrbit(involutions, [ball], 6), x));
      }),
      { ...SEED, numRuns: 200 },
    );
    expect(deep).toBeGreaterThan(runs * 0.4);
  });

  /**
   * A cube-type sphairahedron (Figs. 26–28): finite (six overlapping inversion spheres, the seed
   * ball reaching into them) or infinite (three planes, three spheres, a box seed), and a point
   * around one of its sphere faces.
   */
  const sphairahedronIn = (z: number) =>
    fc.record({
      type: fc.constantFrom(...CUBE_TYPES),
      zb: real(-z, z),
      zc: real(-z, z),
      finite: fc.boolean(),
      lift: real(0, 1),
      radius: real(1, 2),
      face: fc.integer({ min: 0, max: 2 }),
      dir: unit3,
      t: real(0, 1.6),
    });
  const sphairahedron = sphairahedronIn(0.3);

  type SphairahedronSample = typeof sphairahedron extends fc.Arbitrary<infer T> ? T : never;

  /** The inversion centre of the samples' finite form: the default one, lifted. */
  function finiteCentre(inf: InfiniteSphairahedron, lift: number): Vec3 {
    const inv = defaultInversionSphere(inf);
    return [inv.center[0], inv.center[1], inv.center[2] + lift];
  }

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
      const fin = finiteSphairahedron(inf.value, {
        center: finiteCentre(inf.value, c.lift),
        radius: c.radius,
      });
      if (!fin.ok) return null;
      elements = finiteElements(fin.value);
      seed = { kind: 'sphere', nodeId: 's', sphere: fin.value.seed, color, clipped: true };
      face = fin.value.spheres[3 + c.face]!;
    }
    const scene = scene3d(elements, [seed], { maxIterations: 40 });
    const inversion = c.finite ? { center: finiteCentre(inf.value, c.lift), radius: c.radius } : null;
    return { scene, inversion, x: add3(face.center, scale3(c.dir, c.t * face.radius)) };
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

  /**
   * The same shapes with the tile as the seed (docs/math-3d.md "The tile as a seed"), whole (40
   * steps) or grown by 1, 2 or 5 inversions: the orbit probed is the one the tracer draws with that
   * budget (a point is in it when its IIS ends inside the tile within the budget).
   */
  it('leaves no orbit point in the ball it claims empty (the tile seed, whole and step-limited)', () => {
    let tested = 0;
    const steps = fc.sample(fc.constantFrom(1, 2, 5, 40), { seed: SEED.seed, numRuns: 60 });
    fc.sample(sphairahedron, { seed: SEED.seed + 1, numRuns: 60 }).forEach((c, i) => {
      const k = sphairahedronCase(c);
      if (!k) return;
      const inf = infiniteSphairahedron(c.type, c.zb, c.zc);
      if (!inf.ok) return;
      const seed = k.scene.seeds[0]!;
      const tile: Seed3d = {
        kind: 'tile',
        nodeId: 's',
        tile: sphairahedronTile(inf.value, k.inversion),
        color: seed.color,
        clipped: true,
      };
      const scene = { ...k.scene, seeds: [tile], maxIterations: steps[i]! };
      const { de } = walk3d(prepareTrace3d(scene), ...k.x, true);
      expect(de).toBeGreaterThanOrEqual(0);
      if (!(de > 1e-9)) return;
      tested++;
      for (const rho of SHELLS.filter((r) => r < 1))
        for (const p of PROBES) {
          const s = sampleSpace(scene, add3(k.x, scale3(p, rho * de)));
          // Drawn: the walk ends inside the tile within the budget, at its last step too.
          expect(s.distance !== null && s.distance < 0).toBe(false);
        }
    });
    expect(tested).toBeGreaterThan(20);
  }, 300_000);

  it('leaves no orbit point in the ball it claims empty outside the parameter space (bridges, tunnels: faces crossing in new ways)', () => {
    let tested = 0;
    const classes = new Set<string>();
    for (const c of fc.sample(sphairahedronIn(1.4), { seed: SEED.seed, numRuns: 120 })) {
      const cls = spaceClass(infiniteSphairahedron(c.type, c.zb, c.zc));
      if (cls === 'valid' || cls === 'degenerate') continue;
      const k = sphairahedronCase(c);
      if (!k) continue;
      const { de } = walk3d(prepareTrace3d(k.scene), ...k.x, true);
      expect(de).toBeGreaterThanOrEqual(0);
      if (!(de > 1e-9)) continue;
      classes.add(cls);
      tested++;
      expect(orbitWithin(k.scene, k.x, de)).toBeGreaterThan(0.99);
      if (tested >= 30) break;
    }
    expect(tested).toBeGreaterThan(15);
    expect([...classes].sort()).toEqual(['bridge', 'bridge-tunnel', 'tunnel']);
  }, 300_000);
});
