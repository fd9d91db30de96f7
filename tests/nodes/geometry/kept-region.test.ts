import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../../nodes/core/values.ts';
import {
  commonInteriorPoint,
  depthInSide,
  flipSide,
  isBounded,
  type KeptSide,
} from '../../../nodes/geometry/kept-region.ts';

const SEED = { seed: 42, numRuns: 300 } as const;

/** The half-plane kept by the line a → b (its left side). */
const left = (a: Vec2, b: Vec2): KeptSide => {
  const d = Math.hypot(b[0] - a[0], b[1] - a[1]);
  return { kind: 'half-plane', q: a, n: [-(b[1] - a[1]) / d, (b[0] - a[0]) / d] };
};
const outside = (c: Vec2, r: number): KeptSide => ({ kind: 'disk', c, r, keepInside: false });
const A: Vec2 = [0, 0];
const B: Vec2 = [2, 0];
const C: Vec2 = [0.5, 1.5];
const inAll = (sides: readonly KeptSide[], p: Vec2) => sides.every((s) => depthInSide(s, p) > 0);

describe('kept sides', () => {
  it('a half-plane keeps its left side, a circle its outside; flipping keeps the other', () => {
    expect(depthInSide(left(A, B), [1, 1])).toBeCloseTo(1);
    expect(depthInSide(left(A, B), [1, -1])).toBeCloseTo(-1);
    expect(depthInSide(outside([0, 0], 1), [3, 0])).toBeCloseTo(2);
    expect(depthInSide(flipSide(outside([0, 0], 1)), [3, 0])).toBeCloseTo(-2);
    expect(depthInSide(flipSide(left(A, B)), [1, 1])).toBeCloseTo(-1);
  });

  it('the anticlockwise triangle keeps its inside: bounded; AB, AC, BC keeps an unbounded region', () => {
    const good = [left(A, B), left(B, C), left(C, A)];
    const p = commonInteriorPoint(good);
    expect(p).not.toBeNull();
    expect(inAll(good, p!)).toBe(true);
    expect(isBounded(good)).toBe(true);
    const teacher = [left(A, B), left(A, C), left(B, C)];
    expect(commonInteriorPoint(teacher)).not.toBeNull();
    expect(isBounded(teacher)).toBe(false);
  });

  it('the clockwise triangle keeps no common region', () => {
    expect(commonInteriorPoint([left(A, C), left(C, B), left(B, A)])).toBeNull();
  });

  it('finds thin and cusped regions: a sliver strip, and the gap between three kissing circles', () => {
    const strip = [left([0, 0], [1, 0]), left([1, 1e-4], [0, 1e-4])];
    expect(commonInteriorPoint(strip)).not.toBeNull();
    expect(commonInteriorPoint([left([0, 0], [1, 0]), left([1, 0], [0, 0])])).toBeNull();
    // Three unit circles touching pairwise, and a big circle around them kept from inside: the only
    // common parts are the cusped triangle between them and the three gaps along the big rim.
    const h = Math.sqrt(3);
    const kissing = [outside([-1, 0], 1), outside([1, 0], 1), outside([0, h], 1)];
    const big = flipSide(outside([0, h / 3], 1 + 2 / h));
    const p = commonInteriorPoint([...kissing, big]);
    expect(p).not.toBeNull();
    expect(inAll([...kissing, big], p!)).toBe(true);
    expect(isBounded([...kissing, big])).toBe(true);
  });

  it('no sides: the whole plane; two lines are never bounded', () => {
    expect(commonInteriorPoint([])).toEqual([0, 0]);
    expect(isBounded([left(A, B), left(B, C)])).toBe(false);
  });

  const pt = fc.tuple(
    fc.double({ min: -5, max: 5, noNaN: true }),
    fc.double({ min: -5, max: 5, noNaN: true }),
  );
  const side = fc.oneof(
    fc
      .tuple(pt, fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }))
      .map(([q, t]): KeptSide => ({ kind: 'half-plane', q: q as Vec2, n: [Math.cos(t), Math.sin(t)] })),
    fc
      .tuple(pt, fc.double({ min: 0.1, max: 4, noNaN: true }), fc.boolean())
      .map(([c, r, keepInside]): KeptSide => ({ kind: 'disk', c: c as Vec2, r, keepInside })),
  );

  it('property: a point it returns lies inside every kept side', () => {
    fc.assert(
      fc.property(fc.array(side, { minLength: 1, maxLength: 7 }), (sides) => {
        const p = commonInteriorPoint(sides);
        if (p) expect(inAll(sides, p)).toBe(true);
      }),
      SEED,
    );
  });

  it('property: when some sampled point lies well inside every side, a common point is found', () => {
    fc.assert(
      fc.property(
        fc.array(side, { minLength: 1, maxLength: 6 }),
        fc.array(pt, { minLength: 20, maxLength: 20 }),
        (sides, probes) => {
          const witness = probes.find((p) => sides.every((s) => depthInSide(s, p as Vec2) > 1e-3));
          if (witness) expect(commonInteriorPoint(sides)).not.toBeNull();
        },
      ),
      SEED,
    );
  });

  it('property: a regular polygon kept from inside is bounded, flipped keeps nothing; a triangle with one edge flipped is unbounded', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 3, max: 8 }),
        fc.double({ min: 0.5, max: 3, noNaN: true }),
        pt,
        fc.integer({ min: 0, max: 7 }),
        (k, r, c, which) => {
          const corners = Array.from(
            { length: k },
            (_, i): Vec2 => [
              c[0] + r * Math.cos((2 * Math.PI * i) / k),
              c[1] + r * Math.sin((2 * Math.PI * i) / k),
            ],
          );
          const sides = corners.map((p, i) => left(p, corners[(i + 1) % k]));
          expect(isBounded(sides)).toBe(true);
          expect(commonInteriorPoint(sides)).not.toBeNull();
          expect(commonInteriorPoint(sides.map(flipSide))).toBeNull();
          // Three edges spread round a regular polygon bound a triangle (a square has no such three);
          // with one flipped, they don't.
          if (k === 4) return;
          const triangle = [sides[0], sides[Math.floor(k / 3)], sides[Math.floor((2 * k) / 3)]];
          const oneFlipped = triangle.map((s, i) => (i === which % 3 ? flipSide(s) : s));
          expect(isBounded(triangle)).toBe(true);
          expect(isBounded(oneFlipped)).toBe(false);
          expect(commonInteriorPoint(oneFlipped)).not.toBeNull();
        },
      ),
      SEED,
    );
  });
});
