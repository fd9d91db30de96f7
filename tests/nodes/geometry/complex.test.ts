import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type Complex, cabs, cdiv, cmul, csqrt, csub } from '../../../nodes/geometry/complex.ts';

const SEED = { seed: 42, numRuns: 300 } as const;
const part = fc.double({ min: -1e3, max: 1e3, noNaN: true });
const cplx = fc.tuple(part, part) as fc.Arbitrary<Complex>;

describe('complex numbers', () => {
  it('√z squares back to z and has a non-negative real part (principal root)', () => {
    fc.assert(
      fc.property(cplx, (z) => {
        const r = csqrt(z);
        expect(r[0]).toBeGreaterThanOrEqual(0);
        expect(cabs(csub(cmul(r, r), z))).toBeLessThanOrEqual(1e-12 * Math.max(1, cabs(z)));
      }),
      SEED,
    );
  });

  it('(z/w)·w = z', () => {
    fc.assert(
      fc.property(cplx, cplx, (z, w) => {
        fc.pre(cabs(w) > 1e-3);
        expect(cabs(csub(cmul(cdiv(z, w), w), z))).toBeLessThanOrEqual(1e-9 * Math.max(1, cabs(z)));
      }),
      SEED,
    );
  });

  it('known values: i² = −1, √−4 = 2i, (1 + i)/(1 − i) = i', () => {
    expect(cmul([0, 1], [0, 1])).toEqual([-1, 0]);
    expect(csqrt([-4, 0])).toEqual([0, 2]);
    expect(cdiv([1, 1], [1, -1])).toEqual([0, 1]);
  });
});
