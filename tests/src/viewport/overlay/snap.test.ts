import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../../../nodes/core/values.ts';
import { dist } from '../../../../nodes/geometry/vec.ts';
import {
  niceGridStep,
  pointAtRadius,
  snapAngle,
  snapRadiusToStep,
  snapRadiusToTangent,
  snapToGrid,
  tangentRadii,
} from '../../../../src/viewport/overlay/snap.ts';

const coord = fc.double({ min: -1e3, max: 1e3, noNaN: true, noDefaultInfinity: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const positive = fc.double({ min: 1e-3, max: 1e3, noNaN: true, noDefaultInfinity: true });
const step = fc.constantFrom(0.001, 0.002, 0.005, 0.01, 0.1, 0.2, 0.5, 1, 2, 5, 10, 100);
const FIFTEEN_DEGREES = Math.PI / 12;

describe('niceGridStep', () => {
  it('picks 1, 2 or 5 × 10^k with cells of 20–50 px at any zoom', () => {
    fc.assert(
      fc.property(fc.double({ min: 1e-4, max: 1e7, noNaN: true }), (ppw) => {
        const s = niceGridStep(ppw, 20);
        const k = Math.floor(Math.log10(s) + 1e-9);
        const m = Math.round(s / 10 ** k);
        expect([1, 2, 5]).toContain(m);
        expect(Math.abs(s - m * 10 ** k)).toBeLessThan(1e-9 * s);
        const cell = s * ppw;
        expect(cell).toBeGreaterThanOrEqual(20 * (1 - 1e-9));
        expect(cell).toBeLessThan(50 + 1e-6);
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('gives the steps a user expects at familiar zooms', () => {
    // A 600 px tall pane showing 4 world units: 150 px per unit → 20 px = 0.133 → step 0.2 (30 px).
    expect(niceGridStep(150, 20)).toBeCloseTo(0.2, 12);
    expect(niceGridStep(20, 20)).toBeCloseTo(1, 12);
    expect(niceGridStep(1000, 20)).toBeCloseTo(0.02, 12);
    expect(niceGridStep(0.5, 20)).toBeCloseTo(50, 9);
  });
});

describe('snapToGrid', () => {
  it('is idempotent and moves each coordinate by at most half a cell', () => {
    fc.assert(
      fc.property(point, step, (p, s) => {
        const q = snapToGrid(p, s);
        expect(snapToGrid(q, s)).toEqual(q);
        expect(Math.abs(q[0] - p[0])).toBeLessThanOrEqual(s / 2 + 1e-9);
        expect(Math.abs(q[1] - p[1])).toBeLessThanOrEqual(s / 2 + 1e-9);
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('lands on grid crossings', () => {
    expect(snapToGrid([0.33, -0.74], 0.2)).toEqual([0.4, -0.8]);
    expect(snapToGrid([1.24, 2.26], 0.5)).toEqual([1, 2.5]);
  });
});

describe('snapAngle', () => {
  it('turns to a multiple of π/12 about the pivot and keeps the length', () => {
    fc.assert(
      fc.property(point, point, (p, pivot) => {
        fc.pre(dist(p, pivot) > 1e-6);
        const q = snapAngle(p, pivot, 12);
        expect(dist(q, pivot)).toBeCloseTo(dist(p, pivot), 6);
        const k = Math.atan2(q[1] - pivot[1], q[0] - pivot[0]) / FIFTEEN_DEGREES;
        expect(Math.abs(k - Math.round(k))).toBeLessThan(1e-6);
        // ... and to the nearest one: it turns by at most 7.5°.
        const turn = Math.acos(
          Math.min(
            1,
            ((p[0] - pivot[0]) * (q[0] - pivot[0]) + (p[1] - pivot[1]) * (q[1] - pivot[1])) /
              dist(p, pivot) ** 2,
          ),
        );
        expect(turn).toBeLessThanOrEqual(FIFTEEN_DEGREES / 2 + 1e-6);
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('makes an almost horizontal line horizontal and a 44° one 45°', () => {
    const q = snapAngle([3, 0.1], [1, 0], 12);
    expect(q[1]).toBeCloseTo(0, 12);
    expect(q[0]).toBeCloseTo(1 + Math.hypot(2, 0.1), 12);
    const r = snapAngle([Math.cos(0.768), Math.sin(0.768)], [0, 0], 12);
    expect(r[0]).toBeCloseTo(Math.SQRT1_2, 12);
    expect(r[1]).toBeCloseTo(Math.SQRT1_2, 12);
  });

  it('leaves a point on the pivot alone', () => {
    expect(snapAngle([2, 3], [2, 3], 12)).toEqual([2, 3]);
  });
});

describe('tangency', () => {
  const circle = fc.record({ c: point, r: positive });

  it('every tangent radius makes the circles touch: |c1 − c2| = r1 + r2 or |r1 − r2|', () => {
    fc.assert(
      fc.property(point, circle, (c, other) => {
        const d = dist(c, other.c);
        fc.pre(d > 1e-6);
        const radii = tangentRadii(c, other);
        // Two tangencies, except when c lies on the other rim (then only the enclosing one).
        expect(radii.length).toBe(d === other.r ? 1 : 2);
        for (const r of radii) {
          expect(r).toBeGreaterThan(0);
          const gap = Math.min(Math.abs(d - (r + other.r)), Math.abs(d - Math.abs(r - other.r)));
          expect(gap).toBeLessThan(1e-9 * (1 + d + other.r));
        }
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('snaps a radius within tolerance to the closest tangency, and leaves it alone otherwise', () => {
    fc.assert(
      fc.property(point, circle, positive, (c, other, radius) => {
        const d = dist(c, other.c);
        fc.pre(d > 1e-6);
        const tolerance = 0.1 * other.r;
        const snap = snapRadiusToTangent(c, radius, [other], tolerance);
        const nearest = Math.min(...tangentRadii(c, other).map((r) => Math.abs(r - radius)));
        if (nearest > tolerance) {
          expect(snap).toBeNull();
          return;
        }
        expect(snap).not.toBeNull();
        expect(Math.abs(snap!.radius - radius)).toBeCloseTo(nearest, 9);
        const r = snap!.radius;
        const rim = pointAtRadius(c, [c[0] + 1, c[1] + 2], r);
        expect(dist(rim, c)).toBeCloseTo(r, 6);
        const touch = Math.min(Math.abs(d - (r + other.r)), Math.abs(d - Math.abs(r - other.r)));
        expect(touch).toBeLessThan(1e-9 * (1 + d + other.r));
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('chooses the nearest of several circles, outside or inside', () => {
    const others = [
      { c: [3, 0] as Vec2, r: 1 }, // external tangency at r = 2, enclosing at r = 4
      { c: [0, 0.5] as Vec2, r: 3 }, // inside it at r = 2.5
    ];
    expect(snapRadiusToTangent([0, 0], 1.95, others, 0.1)).toEqual({ radius: 2, index: 0 });
    expect(snapRadiusToTangent([0, 0], 2.45, others, 0.1)).toEqual({ radius: 2.5, index: 1 });
    expect(snapRadiusToTangent([0, 0], 3.45, others, 0.1)).toEqual({ radius: 3.5, index: 1 });
    expect(snapRadiusToTangent([0, 0], 3.0, others, 0.1)).toBeNull();
  });

  it('never calls concentric circles tangent', () => {
    expect(tangentRadii([1, 1], { c: [1, 1], r: 2 })).toEqual([]);
  });
});

describe('snapRadiusToStep', () => {
  it('rounds the radius to a positive multiple of the step and keeps the direction', () => {
    const q = snapRadiusToStep([1, 1], [1 + 0.93 * 0.6, 1 + 0.93 * 0.8], 0.2);
    expect(dist(q, [1, 1])).toBeCloseTo(1, 12);
    expect((q[1] - 1) / (q[0] - 1)).toBeCloseTo(0.8 / 0.6, 12);
    expect(dist(snapRadiusToStep([0, 0], [0.01, 0], 0.5), [0, 0])).toBeCloseTo(0.5, 12);
  });
});
