/**
 * A seed solid's distance (nodes/formula/solid.ts) never exceeds the distance to the solid: checked
 * against points of the solid itself (any point s of the solid bounds the distance by |p − s|), for
 * a true distance (the torus) and for a steep formula divided by its sampled slope.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Seed3d, Vec3 } from '../../../nodes/core/scene-3d.ts';
import { sampledSlope, solidRun, solidSeedDistance } from '../../../nodes/formula/solid.ts';
import { SLOPE_MARGIN, TORUS } from '../../../nodes/types/seed-solid.ts';

const SEED = { seed: 20261128, numRuns: 300 } as const;
const real = (min: number, max: number) => fc.double({ min, max, noNaN: true, noDefaultInfinity: true });
const point = fc.tuple(real(-2, 2), real(-2, 2), real(-2, 2)) as fc.Arbitrary<Vec3>;

function solid(
  formula: string,
  numbers: [number, number, number],
  radius: number,
  center: Vec3 = [0.3, -0.2, 0.1],
) {
  const run = solidRun(formula)!;
  const { slope } = sampledSlope(run, numbers, radius);
  const seed: Extract<Seed3d, { kind: 'formula' }> = {
    kind: 'formula',
    nodeId: 's',
    center,
    radius,
    formula,
    numbers,
    slope: slope > 1.001 ? slope * SLOPE_MARGIN : 1,
    color: [1, 1, 1],
  };
  return { seed, slope };
}

/** Points of the torus (radii R, r about the z axis through c): (R + ρ cos v)(cos u, sin u), ρ sin v. */
const torusPoint = (c: Vec3, R: number, r: number, u: number, v: number, rho: number): Vec3 => [
  c[0] + (R + rho * r * Math.cos(v)) * Math.cos(u),
  c[1] + (R + rho * r * Math.cos(v)) * Math.sin(u),
  c[2] + rho * r * Math.sin(v),
];

describe('seed solid distance', () => {
  it('the torus formula is a distance: its sampled slope is 1', () => {
    const { slope } = solid(TORUS, [0.32, 0.1, 0], 0.5);
    expect(slope).toBeGreaterThan(0.95);
    expect(slope).toBeLessThan(1.001);
  });

  it('is the exact torus distance inside the ball, and 0 on the surface', () => {
    const { seed } = solid(TORUS, [0.32, 0.1, 0], 0.5, [0, 0, 0]);
    expect(solidSeedDistance(seed, 0.32, 0, 0)).toBeCloseTo(-0.1, 12);
    expect(solidSeedDistance(seed, 0.42, 0, 0)).toBeCloseTo(0, 12);
    expect(solidSeedDistance(seed, 0, 0, 0)).toBeCloseTo(0.22, 12); // the hole's centre
    // beyond the ball only the ball counts (the formula's slope is known inside it only)
    expect(solidSeedDistance(seed, 3, 0, 0)).toBeCloseTo(2.5, 12);
  });

  for (const [name, formula, factor] of [
    ['a true distance (torus)', TORUS, 1],
    ['a steep formula (torus × 3)', `3 * (${TORUS})`, 3],
    [
      'a non-distance (the torus’s implicit quartic)',
      '(x*x + y*y + z*z + a*a - b*b)**2 - 4*a*a*(x*x + y*y)',
      0,
    ],
  ] as const) {
    it(`never exceeds |p − s| for points s of the solid: ${name}`, () => {
      const { seed, slope } = solid(formula, [0.32, 0.1, 0], 0.5);
      if (factor > 0) expect(slope).toBeGreaterThan(factor * 0.95);
      fc.assert(
        fc.property(point, real(0, 2 * Math.PI), real(0, 2 * Math.PI), real(0, 1), (p, u, v, rho) => {
          const s = torusPoint(seed.center, 0.32, 0.1, u, v, rho);
          const d = solidSeedDistance(seed, ...p);
          expect(d).toBeLessThanOrEqual(
            Math.hypot(p[0] - s[0], p[1] - s[1], p[2] - s[2]) * (1 + 1e-9) + 1e-12,
          );
        }),
        SEED,
      );
    });
  }

  it('a formula undefined at a point (NaN) counts as on the surface there; outside the ball, the ball', () => {
    const { seed } = solid('sqrt(x) - 0.1', [0, 0, 0], 0.5, [0, 0, 0]);
    expect(solidSeedDistance(seed, -0.2, 0, 0)).toBe(0);
    expect(solidSeedDistance(seed, -2, 0, 0)).toBeCloseTo(1.5, 12);
    expect(seed.slope).toBeGreaterThan(1); // √x is steep near 0: its sampled slope divides
    expect(solidSeedDistance(seed, 0.25, 0, 0)).toBeCloseTo(0.4 / seed.slope, 12); // (√0.25 − 0.1) / L
  });
});
