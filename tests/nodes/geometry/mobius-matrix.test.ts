import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Circle, Vec2 } from '../../../nodes/core/values.ts';
import { invertPoint } from '../../../nodes/geometry/circle.ts';
import { type Complex, cabs, cmul } from '../../../nodes/geometry/complex.ts';
import {
  applyMatrix,
  classifyMatrix,
  det,
  inverseMatrix,
  isAffine,
  isometricCircles,
  type MobiusMatrix,
  normalizeMatrix,
  twoCircleMatrix,
} from '../../../nodes/geometry/mobius-matrix.ts';
import { dist } from '../../../nodes/geometry/vec.ts';

const SEED = { seed: 42, numRuns: 300 } as const;
const part = fc.double({ min: -3, max: 3, noNaN: true });
const cplx = fc.tuple(part, part) as fc.Arbitrary<Complex>;
const circle = fc.record({
  c: cplx,
  r: fc.double({ min: 0.2, max: 3, noNaN: true }),
}) as fc.Arbitrary<Circle>;
const near = (z: Vec2, w: Vec2, digits = 7) => {
  expect(z[0]).toBeCloseTo(w[0], digits);
  expect(z[1]).toBeCloseTo(w[1], digits);
};

describe('Möbius matrices', () => {
  it('normalising makes det = 1 and keeps the map', () => {
    fc.assert(
      fc.property(cplx, cplx, cplx, cplx, cplx, (a, b, c, d, z) => {
        const m = { a, b, c, d };
        const n = normalizeMatrix(m);
        fc.pre(n !== null && cabs(det(m)) > 1e-3);
        const D = det(n!);
        expect(D[0]).toBeCloseTo(1, 9);
        expect(D[1]).toBeCloseTo(0, 9);
        const w1 = applyMatrix(m, z);
        const w2 = applyMatrix(n!, z);
        fc.pre(w1 !== null && w2 !== null && cabs(w1) < 1e3);
        near(w1!, w2!, 6);
      }),
      SEED,
    );
  });

  it('det 0 is rejected; c = 0 is affine', () => {
    expect(normalizeMatrix({ a: [1, 0], b: [2, 0], c: [2, 0], d: [4, 0] })).toBeNull();
    expect(isAffine(normalizeMatrix({ a: [2, 0], b: [1, 0], c: [0, 0], d: [0.5, 0] })!)).toBe(true);
  });

  it('the matrix of σ_C2∘σ_C1 maps points like the two inversions', () => {
    fc.assert(
      fc.property(circle, circle, cplx, (c1, c2, z) => {
        fc.pre(dist(c1.c, c2.c) > 0.05 || Math.abs(c1.r - c2.r) > 0.05);
        const m = twoCircleMatrix(c1, c2)!;
        const a = invertPoint(c1, z);
        fc.pre(a !== null && dist(z, c1.c) > 0.05 && dist(a, c2.c) > 0.05);
        const viaCircles = invertPoint(c2, a!)!;
        const viaMatrix = applyMatrix(m, z)!;
        fc.pre(cabs(viaCircles) < 100);
        near(viaMatrix, viaCircles, 6);
        // …and the trace agrees with the two-circle formula τ = (r1² + r2² − d²)/(r1 r2), up to sign.
        const d = dist(c1.c, c2.c);
        const tau = (c1.r ** 2 + c2.r ** 2 - d * d) / (c1.r * c2.r);
        const t = [m.a[0] + m.d[0], m.a[1] + m.d[1]];
        expect(Math.abs(t[0])).toBeCloseTo(Math.abs(tau), 6);
        expect(t[1]).toBeCloseTo(0, 6);
      }),
      SEED,
    );
  });

  it('g maps I(g) onto I(g⁻¹) isometrically (|g′| = 1 there), and g⁻¹ undoes g', () => {
    const m = normalizeMatrix({ a: [1.2, 0.4], b: [0.3, -0.5], c: [0.8, 0.2], d: [1.1, -0.3] })!;
    const { forward, backward } = isometricCircles(m);
    expect(forward.r).toBeCloseTo(backward.r, 12);
    for (let k = 0; k < 12; k++) {
      const t = (k * Math.PI) / 6;
      const z: Vec2 = [forward.c[0] + forward.r * Math.cos(t), forward.c[1] + forward.r * Math.sin(t)];
      const w = applyMatrix(m, z)!;
      expect(dist(w, backward.c)).toBeCloseTo(backward.r, 9);
      const h = 1e-6;
      const scale = dist(applyMatrix(m, [z[0] + h, z[1]])!, applyMatrix(m, [z[0] - h, z[1]])!) / (2 * h);
      expect(scale).toBeCloseTo(1, 5);
      near(applyMatrix(inverseMatrix(m), w)!, z, 9);
    }
  });

  it('classifies by the trace', () => {
    const mk = (a: Complex, d: Complex, c: Complex = [1, 0]): MobiusMatrix => {
      // b = (ad − 1)/c so that det = 1.
      const ad = cmul(a, d);
      const num: Complex = [ad[0] - 1, ad[1]];
      const cc = c[0] * c[0] + c[1] * c[1];
      return { a, b: [(num[0] * c[0] + num[1] * c[1]) / cc, (num[1] * c[0] - num[0] * c[1]) / cc], c, d };
    };
    expect(classifyMatrix(mk([1.25, 0], [1.25, 0])).type).toBe('hyperbolic');
    const hyp = classifyMatrix(mk([2, 0], [0.5, 0]));
    expect(hyp.multiplier![0]).toBeCloseTo(4, 12); // conjugate to z ↦ 4z
    expect(classifyMatrix(mk([1, 0], [1, 0])).type).toBe('parabolic');
    expect(classifyMatrix(mk([-1, 0], [-1, 0])).type).toBe('parabolic');
    const ell = classifyMatrix(mk([0.5, 0], [0.5, 0]));
    expect(ell.type).toBe('elliptic');
    expect(ell.rotation).toBeCloseTo((2 * Math.PI) / 3, 12); // τ = 1 = 2cos(θ/2): θ = 120°
    expect(classifyMatrix(mk([1, 0.5], [1, 0.5])).type).toBe('loxodromic');
    expect(classifyMatrix(mk([0, 1], [0, 1])).type).toBe('loxodromic'); // τ = 2i: τ² = −4
  });
});
