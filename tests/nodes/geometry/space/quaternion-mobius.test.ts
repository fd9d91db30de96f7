/**
 * Quaternion Möbius transformations of space (docs/math-3d.md "Quaternion Kleinian groups"):
 * the Sp^K(1,1) conditions, inverses, the action on points, and fixed points.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { qNorm, qSub } from '../../../../nodes/geometry/space/quaternion.ts';
import {
  attractingFixedPoint,
  mobiusQ,
  pseudoDeterminant,
  Q_IDENTITY,
  type QMatrix,
  qmApply,
  qmInverse,
  qmMul,
  qPointToSpace,
  sakugawaGenerators,
  spProblem,
} from '../../../../nodes/geometry/space/quaternion-mobius.ts';
import { dist3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { point3, SEED } from './arbitraries.ts';

const closeMatrix = (m: QMatrix, n: QMatrix, tol: number) => {
  for (const key of ['a', 'b', 'c', 'd'] as const) expect(qNorm(qSub(m[key], n[key]))).toBeLessThan(tol);
};

const family = fc.tuple(
  fc.double({ min: -3.9, max: -0.1, noNaN: true }),
  fc.double({ min: -1.5, max: 1.5, noNaN: true }),
  fc.double({ min: -1.5, max: 1.5, noNaN: true }),
);

describe('quaternion Möbius transformations', () => {
  it('Sakugawa’s generators are Sp^K(1,1) matrices, and M M⁻¹ = M⁻¹ M = I', () => {
    fc.assert(
      fc.property(family, ([x, ta, tb]) => {
        for (const g of sakugawaGenerators(x, ta, tb)) {
          expect(spProblem(g)).toBeNull();
          expect(pseudoDeterminant(g)[0]).toBeCloseTo(1, 9);
          closeMatrix(qmMul(g, qmInverse(g)), Q_IDENTITY, 1e-9);
          closeMatrix(qmMul(qmInverse(g), g), Q_IDENTITY, 1e-9);
        }
      }),
      SEED,
    );
  });

  it('maps points of space to points of space, and M⁻¹ undoes M', () => {
    fc.assert(
      fc.property(family, point3, ([x, ta, tb], p) => {
        for (const g of sakugawaGenerators(x, ta, tb)) {
          const [u, v] = qmApply(g, [
            [p[0], p[1], p[2], 0],
            [1, 0, 0, 0],
          ]);
          const image = qPointToSpace([u, v]);
          if (!image || dist3(image, [0, 0, 0]) > 1e6) continue;
          // No k part: the image u v⁻¹ is again x + yi + zj.
          const back = mobiusQ(qmInverse(g), image)!;
          expect(dist3(back, p)).toBeLessThan(1e-6 * Math.max(1, dist3(p, [0, 0, 0]) ** 2));
        }
      }),
      SEED,
    );
  });

  it('B is the screw x ↦ q_B (x + 1) q_B⁻¹: a unit step along x and a turn by 2θ_B', () => {
    const [, b] = sakugawaGenerators(-2, 0.3, Math.PI / 4);
    const image = mobiusQ(b, [0.5, 1, 0])!;
    expect(image[0]).toBeCloseTo(1.5, 12);
    expect(image[1]).toBeCloseTo(0, 12);
    expect(image[2]).toBeCloseTo(1, 12);
  });

  it('finds the attracting fixed point of a loxodromic (a complex one, checked against the quadratic formula)', () => {
    // M = [[1 + i, 1], [i, 1]]: det = 1, trace 2 + i: loxodromic. Fixed points z = ((a − d) ± √((a + d)² − 4)) / 2c,
    // a − d = i.
    const m: QMatrix = { a: [1, 1, 0, 0], b: [1, 0, 0, 0], c: [0, 1, 0, 0], d: [1, 0, 0, 0] };
    expect(spProblem(m)).toBeNull();
    type C = [number, number];
    const mul = (p: C, q: C): C => [p[0] * q[0] - p[1] * q[1], p[0] * q[1] + p[1] * q[0]];
    const div = (p: C, q: C): C => {
      const n = q[0] ** 2 + q[1] ** 2;
      return [(p[0] * q[0] + p[1] * q[1]) / n, (p[1] * q[0] - p[0] * q[1]) / n];
    };
    const sqrt = (p: C): C => {
      const r = Math.hypot(p[0], p[1]);
      return [Math.sqrt((r + p[0]) / 2), Math.sign(p[1] || 1) * Math.sqrt((r - p[0]) / 2)];
    };
    const disc = sqrt([mul([2, 1], [2, 1])[0] - 4, mul([2, 1], [2, 1])[1]]);
    const roots = [1, -1].map((s) => div([s * disc[0], 1 + s * disc[1]], [0, 2]));
    // The attracting one has |M'(z)| = 1/|cz + d|² < 1.
    const attracting = roots.find(
      (z) => Math.hypot(...mul([0, 1], z).map((v, k) => v + (k === 0 ? 1 : 0))) > 1,
    )!;
    const found = qPointToSpace(attractingFixedPoint(m))!;
    expect(dist3(found, [attracting[0], attracting[1], 0])).toBeLessThan(1e-9);
  });

  it('finds the fixed point that iterating a twisted (quaternion) word converges to, and M·p = p', () => {
    let converged = 0;
    fc.assert(
      fc.property(family, ([x, ta, tb]) => {
        const [a, b] = sakugawaGenerators(x, ta, tb);
        // a a b is loxodromic for most of the family (a b is parabolic: its iterates creep like 1/n).
        const ab = qmMul(qmMul(a, a), b);
        // Brute force: iterate the word from a start point; a loxodromic converges geometrically.
        let q: Vec3 | null = [0.2, 0.1, -0.3];
        for (let n = 0; n < 3000 && q; n++) q = mobiusQ(ab, q);
        const next = q && mobiusQ(ab, q);
        if (!q || !next || dist3(next, q) > 1e-12 || dist3(q, [0, 0, 0]) > 1e3) return;
        converged++;
        const p = qPointToSpace(attractingFixedPoint(ab))!;
        expect(dist3(p, q)).toBeLessThan(1e-7 * Math.max(1, dist3(q, [0, 0, 0])));
        expect(dist3(mobiusQ(ab, p)!, p)).toBeLessThan(1e-7 * Math.max(1, dist3(p, [0, 0, 0])));
      }),
      SEED,
    );
    expect(converged).toBeGreaterThan(20);
  });

  it('finds ∞ as the fixed point of the screw B, and 0 as A’s', () => {
    const [a, b] = sakugawaGenerators(-2, 0.3, 0.3);
    expect(qPointToSpace(attractingFixedPoint(b))).toBeNull();
    const fa = qPointToSpace(attractingFixedPoint(a)) as Vec3;
    expect(dist3(fa, [0, 0, 0])).toBeLessThan(1e-9);
  });

  it('says a matrix is singular or not in Sp^K(1,1)', () => {
    const zero: QMatrix = { a: [0, 0, 0, 0], b: [0, 0, 0, 0], c: [0, 0, 0, 0], d: [0, 0, 0, 0] };
    expect(spProblem(zero)?.kind).toBe('singular');
    const rankOne: QMatrix = { a: [1, 0, 0, 0], b: [1, 0, 0, 0], c: [1, 0, 0, 0], d: [1, 0, 0, 0] };
    expect(spProblem(rankOne)?.kind).toBe('singular');
    // b = k: a b* = −k has a k part, so x ↦ x + k leaves space.
    const offSpace: QMatrix = { a: [1, 0, 0, 0], b: [0, 0, 0, 1], c: [0, 0, 0, 0], d: [1, 0, 0, 0] };
    expect(spProblem(offSpace)).toMatchObject({ kind: 'not-sp' });
    expect(spProblem(offSpace)?.detail).toContain('a b*');
    // Δ = 2i: not a real number.
    const complexDet: QMatrix = { a: [0, 2, 0, 0], b: [0, 0, 0, 0], c: [0, 0, 0, 0], d: [1, 0, 0, 0] };
    expect(spProblem(complexDet)?.kind).toBe('not-sp');
  });
});
