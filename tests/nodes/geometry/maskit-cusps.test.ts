/**
 * The Maskit slice's cusps (docs/math.md "The Maskit slice boundary"): the known values 2i (0/1),
 * −2 + 2i (1/1), −1 + √3 i (1/2); at every cusp the Farey word, multiplied out as matrices of
 * a = [[−iμ, −i], [−i, 0]] and b = [[1, 2], [0, 1]] (not by the trace recursion the solver uses),
 * has trace 2; the cusps are symmetric under p/q ↦ 1 − p/q, μ ↦ −2 − μ̄; and the boundary tests
 * agree with their definitions.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Complex } from '../../../nodes/geometry/complex.ts';
import {
  belowMaskitBoundary,
  fareySequence,
  fareyTrace,
  MASKIT_MAX_DENOMINATOR,
  maskitBoundaryDistance,
  maskitCusp,
  maskitCusps,
} from '../../../nodes/geometry/maskit-cusps.ts';
import { composeMatrices, type MobiusMatrix } from '../../../nodes/geometry/mobius-matrix.ts';

const SEED = { seed: 17, numRuns: 300 } as const;
const A = (mu: Complex): MobiusMatrix => ({ a: [mu[1], -mu[0]], b: [0, -1], c: [0, -1], d: [0, 0] });
const B: MobiusMatrix = { a: [1, 0], b: [2, 0], c: [0, 0], d: [1, 0] };

/** W_{p/q} as a matrix: W_{0/1} = a, W_{1/0} = b, and W of a mediant is W_left · W_right. */
function fareyWord(p: number, q: number, mu: Complex): MobiusMatrix {
  let [left, right] = [A(mu), B];
  let [pl, ql, pr, qr] = [0, 1, 1, 0];
  if (p === 0) return left;
  for (;;) {
    const mid = composeMatrices(left, right);
    const [pm, qm] = [pl + pr, ql + qr];
    if (pm === p && qm === q) return mid;
    if (p * qm < pm * q) [right, pr, qr] = [mid, pm, qm];
    else [left, pl, ql] = [mid, pm, qm];
  }
}

const near = (z: Complex, w: Complex, eps: number) => Math.hypot(z[0] - w[0], z[1] - w[1]) <= eps;

describe('Maskit cusps', () => {
  it('the Farey sequence of order n is every reduced p/q in [0, 1], increasing', () => {
    expect(fareySequence(5).map(([p, q]) => `${p}/${q}`)).toEqual(
      '0/1 1/5 1/4 1/3 2/5 1/2 3/5 2/3 3/4 4/5 1/1'.split(' '),
    );
    // 1 + Σ φ(q), q ≤ 24.
    expect(fareySequence(MASKIT_MAX_DENOMINATOR)).toHaveLength(181);
  });

  it('has the known cusps 2i, −2 + 2i and −1 + √3 i', () => {
    expect(near(maskitCusp(0, 1), [0, 2], 1e-12)).toBe(true);
    expect(near(maskitCusp(1, 1), [-2, 2], 1e-12)).toBe(true);
    expect(near(maskitCusp(1, 2), [-1, Math.sqrt(3)], 1e-12)).toBe(true);
    // 1/3: tr W = i(μ³ + 2μ² + 3μ + 2) = 2, its root with the largest imaginary part.
    expect(near(maskitCusp(1, 3), [-0.5812034746, 1.6938972023], 1e-9)).toBe(true);
  });

  it('the trace recursion is the trace of the word multiplied out (value and derivative)', () => {
    const fractions = fareySequence(12);
    const mu = fc.tuple(
      fc.double({ min: -2, max: 2, noNaN: true }),
      fc.double({ min: 0.5, max: 3, noNaN: true }),
    );
    fc.assert(
      fc.property(fc.nat(fractions.length - 1), mu, (i, [x, y]) => {
        const [p, q] = fractions[i];
        const w = fareyWord(p, q, [x, y]);
        const { t, dt } = fareyTrace(p, q, [x, y]);
        const scale = Math.max(1, Math.hypot(...t));
        expect(near(t, [w.a[0] + w.d[0], w.a[1] + w.d[1]], 1e-9 * scale)).toBe(true);
        // d/dμ by a central difference along the real axis (tr W is holomorphic in μ).
        const h = 1e-6;
        const [tp, tm] = [fareyWord(p, q, [x + h, y]), fareyWord(p, q, [x - h, y])].map(
          (m): Complex => [m.a[0] + m.d[0], m.a[1] + m.d[1]],
        );
        const fd: Complex = [(tp[0] - tm[0]) / (2 * h), (tp[1] - tm[1]) / (2 * h)];
        expect(near(dt, fd, 1e-4 * Math.max(1, Math.hypot(...dt)))).toBe(true);
      }),
      SEED,
    );
  });

  it('at every cusp its word is parabolic: trace 2 (the word multiplied out as matrices)', () => {
    for (const { p, q, mu } of maskitCusps()) {
      const w = fareyWord(p, q, mu);
      const trace: Complex = [w.a[0] + w.d[0], w.a[1] + w.d[1]];
      // The entries grow like |μ|^q: the error is relative to them.
      const size = Math.max(...[w.a, w.b, w.c, w.d].map((z) => Math.hypot(...z)));
      expect(near(trace, [2, 0], 1e-10 * Math.max(1, size)), `${p}/${q}`).toBe(true);
    }
  });

  it('is symmetric: the cusp of 1 − p/q is −2 − conj(μ_{p/q}); every cusp lies in the period', () => {
    const byFraction = new Map(maskitCusps().map((c) => [`${c.p}/${c.q}`, c.mu]));
    for (const { p, q, mu } of maskitCusps()) {
      const mirror = byFraction.get(`${q - p}/${q}`)!;
      expect(near(mirror, [-2 - mu[0], mu[1]], 1e-9), `${p}/${q}`).toBe(true);
      expect(mu[0]).toBeGreaterThanOrEqual(-2);
      expect(mu[0]).toBeLessThanOrEqual(0);
      expect(mu[1]).toBeGreaterThan(1.6);
      expect(mu[1]).toBeLessThanOrEqual(2 + 1e-12);
    }
  });

  it('the cusps go from 2i to −2 + 2i with Re μ decreasing (the boundary is a graph over Re μ here)', () => {
    const xs = maskitCusps().map((c) => c.mu[0]);
    for (let i = 1; i < xs.length; i++) expect(xs[i]).toBeLessThan(xs[i - 1]);
  });
});

describe('Maskit boundary tests', () => {
  it('points well above the boundary are in the slice, points below are not, periodically and mirrored', () => {
    for (const k of [-2, 0, 2, 4]) {
      expect(belowMaskitBoundary(-1 + 2 * k, 2.2, 24)).toBe(false);
      expect(belowMaskitBoundary(-1 + 2 * k, 1.6, 24)).toBe(true);
      expect(belowMaskitBoundary(-1 + 2 * k, -1.6, 24)).toBe(true);
      expect(belowMaskitBoundary(-1 + 2 * k, -2.2, 24)).toBe(false);
      expect(belowMaskitBoundary(0.5 + 2 * k, 0, 24)).toBe(true);
    }
    // Just above and below the 1/2 cusp, and the polyline through 0/1 and 1/1 alone is Im μ = 2.
    expect(belowMaskitBoundary(-1, Math.sqrt(3) + 1e-6, 24)).toBe(false);
    expect(belowMaskitBoundary(-1, Math.sqrt(3) - 1e-6, 24)).toBe(true);
    expect(belowMaskitBoundary(-0.3, 1.99, 1)).toBe(true);
    expect(belowMaskitBoundary(-0.3, 2.01, 1)).toBe(false);
  });

  it('the boundary distance is a true distance: no point nearer than it has another verdict', () => {
    const pt = fc.tuple(
      fc.double({ min: -3, max: 3, noNaN: true }),
      fc.double({ min: -2.5, max: 2.5, noNaN: true }),
    );
    const dir = fc.double({ min: 0, max: 2 * Math.PI, noNaN: true });
    const frac = fc.double({ min: 0, max: 0.999, noNaN: true });
    fc.assert(
      fc.property(pt, dir, frac, fc.integer({ min: 1, max: 24 }), ([x, y], a, f, q) => {
        const d = maskitBoundaryDistance(x, y, q);
        expect(d).toBeGreaterThanOrEqual(0);
        const [x2, y2] = [x + f * d * Math.cos(a), y + f * d * Math.sin(a)];
        // Crossing y = 0 is no boundary: the mirror image of a point below is below.
        expect(belowMaskitBoundary(x2, y2, q)).toBe(belowMaskitBoundary(x, y, q));
      }),
      SEED,
    );
  });
});
