/**
 * The two-generator recipes (docs/math.md "Two-generator recipes"): det 1, the asked traces, and
 * for Grandma's and Jørgensen's a parabolic commutator, tr(abAB) = −2; Riley's two parabolics; the
 * Maskit parameter of a group with one parabolic generator.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type Complex, cmul } from '../../../nodes/geometry/complex.ts';
import { composeMatrices, det, type MobiusMatrix } from '../../../nodes/geometry/mobius-matrix.ts';
import {
  commutatorTrace,
  grandmaRecipe,
  jorgensenRecipe,
  maskitParameter,
  rileyRecipe,
  traceOf,
} from '../../../nodes/geometry/recipes.ts';

const SEED = { seed: 2024, numRuns: 300 };
const part = fc.double({ min: -4, max: 4, noNaN: true });
const complexArb = fc.tuple(part, part).map(([re, im]) => [re, im] as Complex);
/** |z − w| ≤ tol·max(1, |w|). */
const close = (z: Complex, w: Complex, tol = 1e-7) =>
  expect(Math.hypot(z[0] - w[0], z[1] - w[1])).toBeLessThanOrEqual(tol * Math.max(1, Math.hypot(w[0], w[1])));

describe.each([
  ['Grandma', grandmaRecipe],
  ['Jørgensen', jorgensenRecipe],
])('%s’s recipe', (_name, recipe) => {
  it('gives det-1 matrices with traces ta, tb, tr(ab) = tab and tr(abAB) = −2', () => {
    fc.assert(
      fc.property(complexArb, complexArb, (ta, tb) => {
        const g = recipe(ta, tb);
        if (!g) return; // a denominator vanished (measure zero)
        const scale = Math.max(
          1,
          ...[g.a, g.b].flatMap((m) => [m.a, m.b, m.c, m.d].map((z) => Math.hypot(...z))),
        );
        // Cancellation grows with the entries; skip near-singular draws whose entries explode.
        if (scale > 1e4) return;
        const tol = 1e-9 * scale * scale;
        close(det(g.a), [1, 0], tol);
        close(det(g.b), [1, 0], tol);
        close(traceOf(g.a), ta, tol);
        close(traceOf(g.b), tb, tol);
        close(traceOf(composeMatrices(g.a, g.b)), g.tab, tol);
        close(commutatorTrace(g.a, g.b), [-2, 0], 1e-9 * scale ** 4);
      }),
      SEED,
    );
  });
});

describe('Riley’s recipe', () => {
  it('gives two parabolics (traces 2) with tr(ab) = 2 + 2c and tr(abAB) = 2 + 4c²', () => {
    fc.assert(
      fc.property(complexArb, (c) => {
        const g = rileyRecipe(c);
        close(det(g.a), [1, 0]);
        close(det(g.b), [1, 0]);
        close(traceOf(g.a), [2, 0]);
        close(traceOf(g.b), [2, 0]);
        close(traceOf(composeMatrices(g.a, g.b)), [2 + 2 * c[0], 2 * c[1]]);
        const c2 = cmul(c, c);
        close(commutatorTrace(g.a, g.b), [2 + 4 * c2[0], 4 * c2[1]], 1e-9);
      }),
      SEED,
    );
  });
});

describe('maskitParameter', () => {
  const maskit = (mu: Complex): { a: MobiusMatrix; b: MobiusMatrix } => ({
    // a(z) = μ + 1/z as [[−iμ, −i], [−i, 0]] (det 1), b(z) = z + 2.
    a: { a: [mu[1], -mu[0]], b: [0, -1], c: [0, -1], d: [0, 0] },
    b: { a: [1, 0], b: [2, 0], c: [0, 0], d: [1, 0] },
  });

  it('recovers μ from Maskit’s own generators (tr a = −iμ, b parabolic, tr abAB = −2)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -3, max: 3, noNaN: true }),
        fc.double({ min: 0.1, max: 4, noNaN: true }),
        (u, v) => {
          const { a, b } = maskit([u, v]);
          const mu = maskitParameter({ a, b, tab: traceOf(composeMatrices(a, b)) });
          expect(mu).not.toBeNull();
          close(mu as Complex, [u, v], 1e-9);
        },
      ),
      SEED,
    );
  });

  it('Grandma’s recipe with tb = 2 is the Maskit group μ = i·ta (Im μ > 0); ta = tb = 2 gives μ = 2i', () => {
    const g = grandmaRecipe([2, 0], [2, 0]);
    close(g ? (maskitParameter(g) as Complex) : [0, 0], [0, 2]);
    const h = grandmaRecipe([1.7, -0.3], [2, 0]);
    close(h ? (maskitParameter(h) as Complex) : [0, 0], [0.3, 1.7]);
    // Both loxodromic: not a Maskit group.
    const q = grandmaRecipe([1.91, 0.05], [1.91, -0.05]);
    expect(q && maskitParameter(q)).toBeNull();
  });
});
