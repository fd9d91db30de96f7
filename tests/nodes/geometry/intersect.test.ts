import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Circle, Line, Vec2 } from '../../../nodes/core/values.ts';
import { intersectCircles, intersectLineCircle, intersectLines } from '../../../nodes/geometry/intersect.ts';
import { cross, dist, sub } from '../../../nodes/geometry/vec.ts';

const SEED = { seed: 42, numRuns: 300 } as const;
const coord = fc.double({ min: -5, max: 5, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const circle = fc.record({
  c: point,
  r: fc.double({ min: 0.1, max: 4, noNaN: true }),
}) as fc.Arbitrary<Circle>;
const line = fc.record({ a: point, b: point }).filter((l) => dist(l.a, l.b) > 0.1) as fc.Arbitrary<Line>;

/** Distance from p to the infinite line. */
const lineDist = (l: Line, p: Vec2) => Math.abs(cross(sub(l.b, l.a), sub(p, l.a))) / dist(l.a, l.b);

describe('intersections', () => {
  it('line ∩ line lies on both lines', () => {
    fc.assert(
      fc.property(line, line, (l1, l2) => {
        const x = intersectLines(l1, l2);
        if (!x.ok) return;
        const [p] = x.points;
        fc.pre(Math.hypot(...p) < 1e4);
        expect(lineDist(l1, p)).toBeLessThan(1e-8 * Math.max(1, Math.hypot(...p)));
        expect(lineDist(l2, p)).toBeLessThan(1e-8 * Math.max(1, Math.hypot(...p)));
      }),
      SEED,
    );
  });

  it('parallel and coincident lines have no intersection, with the reason', () => {
    const x = intersectLines({ a: [0, 0], b: [1, 1] }, { a: [0, 1], b: [2, 3] });
    expect(x.ok).toBe(false);
    expect(!x.ok && x.reason).toMatch(/parallel/);
    const y = intersectLines({ a: [0, 0], b: [1, 1] }, { a: [2, 2], b: [5, 5] });
    expect(!y.ok && y.reason).toMatch(/coincide/);
  });

  it('line ∩ circle: on both, in the line’s direction, or none when the line misses', () => {
    fc.assert(
      fc.property(line, circle, (l, k) => {
        const x = intersectLineCircle(l, k);
        const gap = lineDist(l, k.c) - k.r;
        if (!x.ok) {
          expect(gap).toBeGreaterThan(-1e-9);
          return;
        }
        expect(gap).toBeLessThan(1e-9);
        const [p1, p2] = x.points;
        for (const p of [p1, p2]) {
          expect(dist(p, k.c)).toBeCloseTo(k.r, 9);
          expect(lineDist(l, p)).toBeLessThan(1e-9);
        }
        const d = sub(l.b, l.a);
        expect((p2[0] - p1[0]) * d[0] + (p2[1] - p1[1]) * d[1]).toBeGreaterThanOrEqual(0);
      }),
      SEED,
    );
  });

  it('a tangent line gives the touching point twice', () => {
    const x = intersectLineCircle({ a: [-3, 1], b: [3, 1] }, { c: [0, 0], r: 1 });
    expect(x.ok && x.points).toEqual([
      [0, 1],
      [0, 1],
    ]);
  });

  it('circle ∩ circle: on both; none when apart, nested or concentric', () => {
    fc.assert(
      fc.property(circle, circle, (k1, k2) => {
        const x = intersectCircles(k1, k2);
        const d = dist(k1.c, k2.c);
        if (!x.ok) {
          expect(d > k1.r + k2.r - 1e-9 || d < Math.abs(k1.r - k2.r) + 1e-9).toBe(true);
          return;
        }
        for (const p of x.points) {
          expect(dist(p, k1.c)).toBeCloseTo(k1.r, 8);
          expect(dist(p, k2.c)).toBeCloseTo(k2.r, 8);
        }
        // p1 right of c1 → c2, p2 left.
        const u = sub(k2.c, k1.c);
        expect(cross(u, sub(x.points[0], k1.c))).toBeLessThanOrEqual(1e-12);
        expect(cross(u, sub(x.points[1], k1.c))).toBeGreaterThanOrEqual(-1e-12);
      }),
      SEED,
    );
    expect(intersectCircles({ c: [0, 0], r: 1 }, { c: [3, 0], r: 1 }).ok).toBe(false);
    expect(intersectCircles({ c: [0, 0], r: 3 }, { c: [0.5, 0], r: 1 }).ok).toBe(false);
    const same = intersectCircles({ c: [0, 0], r: 1 }, { c: [0, 0], r: 1 });
    expect(!same.ok && same.reason).toMatch(/same/);
  });

  it('externally tangent circles meet once (both outputs equal)', () => {
    const x = intersectCircles({ c: [0, 0], r: 1 }, { c: [3, 0], r: 2 });
    expect(x.ok).toBe(true);
    if (x.ok) {
      expect(x.points[0]).toEqual(x.points[1]);
      expect(x.points[0][0]).toBeCloseTo(1, 12);
    }
  });
});
