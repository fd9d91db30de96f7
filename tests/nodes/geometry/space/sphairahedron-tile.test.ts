/**
 * The sphairahedron's tile (docs/math-3d.md "The tile as a seed"): its signed distance has the
 * exact sign of an independent membership test (inside the prism, outside the balls, some ball
 * straight above), never exceeds the distance to the tile (probed by brute force), and the
 * bounding ball holds it. Every published type, finite and infinite.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  defaultInversionSphere,
  infiniteSphairahedron,
  SPHAIRAHEDRON_TYPES,
} from '../../../../nodes/geometry/space/sphairahedron.ts';
import { ballTop } from '../../../../nodes/geometry/space/sphairahedron-shared.ts';
import {
  type SphairahedronTile,
  sphairahedronTile,
  tileSignedDistance,
} from '../../../../nodes/geometry/space/sphairahedron-tile.ts';
import { add3, dist3, dot3, scale3, sub3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { real, SEED, unit3 } from './arbitraries.ts';

/** Membership by the definition: I(p) (or p) in the prism, outside every ball, under one of them. */
function inTile(t: SphairahedronTile, p: Vec3): boolean {
  let q = p;
  if (t.inversion) {
    const v = sub3(p, t.inversion.center);
    q = add3(t.inversion.center, scale3(v, t.inversion.radius ** 2 / dot3(v, v)));
  }
  return (
    q[2] > t.bottom &&
    t.planes.every((f) => dot3(f.normal, sub3(q, f.point)) > 0) &&
    t.balls.every((s) => dist3(q, s.center) > s.radius) &&
    t.balls.some((s) => ballTop(s, q[0], q[1]) > q[2])
  );
}

const sample = fc.record({
  type: fc.constantFrom(...SPHAIRAHEDRON_TYPES),
  zb: real(-0.3, 0.3),
  zc: real(-0.3, 0.3),
  finite: fc.boolean(),
  lift: real(0, 1),
  radius: real(1, 2),
});

/** The tile of a sample, or null when the shape is refused. */
function tileOf(c: typeof sample extends fc.Arbitrary<infer T> ? T : never): SphairahedronTile | null {
  const inf = infiniteSphairahedron(c.type, c.zb, c.zc);
  if (!inf.ok) return null;
  if (!c.finite) return sphairahedronTile(inf.value, null);
  const inv = defaultInversionSphere(inf.value);
  return sphairahedronTile(inf.value, {
    center: [inv.center[0], inv.center[1], inv.center[2] + c.lift],
    radius: c.radius,
  });
}

/** Golden-spiral directions. */
const PROBES: Vec3[] = Array.from({ length: 200 }, (_, k) => {
  const z = 1 - (2 * (k + 0.5)) / 200;
  const a = k * Math.PI * (3 - Math.sqrt(5));
  const h = Math.sqrt(1 - z * z);
  return [h * Math.cos(a), h * Math.sin(a), z];
});
const SHELLS = [0.2, 0.5, 0.8, 0.99];

/** A point near the tile: in its bounding ball (infinite form: near the floor, where the faces are). */
const near = (t: SphairahedronTile, dir: Vec3, f: number): Vec3 =>
  t.inversion
    ? add3(t.bound.center, scale3(dir, f * t.bound.radius))
    : add3([0, 0, t.bottom + 100], scale3(dir, 2 * f));

describe('sphairahedron tile', () => {
  const cases = fc.sample(fc.tuple(sample, unit3, real(0, 1.2)), { seed: SEED.seed, numRuns: 400 });

  it('has the sign of the membership test and a bound never above the distance to the tile', () => {
    let inside = 0;
    let tested = 0;
    for (const [c, dir, f] of cases) {
      const t = tileOf(c);
      if (!t) continue;
      const p = near(t, dir, f);
      const d = tileSignedDistance(t, ...p);
      tested++;
      if (Math.abs(d) > 1e-9) expect(d < 0).toBe(inTile(t, p));
      if (d < 0) inside++;
      if (d > 1e-9)
        for (const rho of SHELLS)
          for (const u of PROBES) expect(inTile(t, add3(p, scale3(u, rho * d)))).toBe(false);
    }
    expect(tested).toBeGreaterThan(200);
    // Both sides are exercised.
    expect(inside).toBeGreaterThan(tested / 20);
    expect(inside).toBeLessThan(tested * 0.9);
  }, 120_000);

  it('lies in its bounding ball', () => {
    for (const [c, dir, f] of cases) {
      const t = tileOf(c);
      if (!t) continue;
      const p = near(t, dir, f);
      if (tileSignedDistance(t, ...p) < 0)
        expect(dist3(p, t.bound.center)).toBeLessThanOrEqual(t.bound.radius);
    }
  });
});
