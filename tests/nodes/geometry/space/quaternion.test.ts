/** Quaternion algebra (docs/math-3d.md "Quaternion Kleinian groups"), property-based with a fixed seed. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  Q_ONE,
  type Quaternion,
  qConj,
  qInv,
  qMul,
  qNorm,
  qStar,
  qSub,
} from '../../../../nodes/geometry/space/quaternion.ts';
import { SEED } from './arbitraries.ts';

const coord = fc.double({ min: -10, max: 10, noNaN: true });
const quat = fc.tuple(coord, coord, coord, coord) as fc.Arbitrary<Quaternion>;
/** A point of space as a quaternion: no k part. */
const vector = fc.tuple(coord, coord, coord).map(([x, y, z]): Quaternion => [x, y, z, 0]);
const near = (p: Quaternion, q: Quaternion, tol: number) =>
  expect(qNorm(qSub(p, q))).toBeLessThanOrEqual(tol);

describe('quaternions', () => {
  it('multiplies by Hamilton’s rules: ij = k = −ji, i² = j² = k² = −1', () => {
    const [i, j, k]: Quaternion[] = [
      [0, 1, 0, 0],
      [0, 0, 1, 0],
      [0, 0, 0, 1],
    ];
    expect(qMul(i, j)).toEqual([0, 0, 0, 1]);
    expect(qMul(j, i)).toEqual([0, 0, 0, -1]);
    expect(qMul(j, k)).toEqual([0, 1, 0, 0]);
    expect(qMul(k, i)).toEqual([0, 0, 1, 0]);
    for (const u of [i, j, k]) expect(qMul(u, u)).toEqual([-1, 0, 0, 0]);
  });

  it('is associative: (pq)r = p(qr)', () => {
    fc.assert(
      fc.property(quat, quat, quat, (p, q, r) => {
        near(qMul(qMul(p, q), r), qMul(p, qMul(q, r)), 1e-9 * Math.max(1, qNorm(p) * qNorm(q) * qNorm(r)));
      }),
      SEED,
    );
  });

  it('has a multiplicative norm |pq| = |p||q| and inverses q q⁻¹ = q⁻¹ q = 1', () => {
    fc.assert(
      fc.property(quat, quat, (p, q) => {
        expect(Math.abs(qNorm(qMul(p, q)) - qNorm(p) * qNorm(q))).toBeLessThan(
          1e-9 * Math.max(1, qNorm(p) * qNorm(q)),
        );
        const inv = qInv(q);
        if (qNorm(q) < 1e-3) return;
        near(qMul(q, inv!), Q_ONE, 1e-9);
        near(qMul(inv!, q), Q_ONE, 1e-9);
      }),
      SEED,
    );
    expect(qInv([0, 0, 0, 0])).toBeNull();
  });

  it('conjugation and the Clifford transposition reverse products; q* fixes points of space', () => {
    fc.assert(
      fc.property(quat, quat, vector, (p, q, v) => {
        const tol = 1e-9 * Math.max(1, qNorm(p) * qNorm(q));
        near(qConj(qMul(p, q)), qMul(qConj(q), qConj(p)), tol);
        near(qStar(qMul(p, q)), qMul(qStar(q), qStar(p)), tol);
        near(qStar(v), v, 0);
      }),
      SEED,
    );
  });
});
