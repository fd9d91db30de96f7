import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Circle, Vec2 } from '../../../nodes/core/values.ts';
import {
  circleThrough3,
  invertCircle,
  invertPoint,
  isDegenerateLine,
  lineNormal,
  reflectPoint,
  signedDistance,
} from '../../../nodes/geometry/circle.ts';
import { cross, dist, len, sub } from '../../../nodes/geometry/vec.ts';

const SEED = { seed: 42, numRuns: 200 } as const;
const coord = fc.double({ min: -5, max: 5, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const radius = fc.double({ min: 0.1, max: 5, noNaN: true });
const circle = fc.record({ c: point, r: radius }) as fc.Arbitrary<Circle>;
const angle = fc.double({ min: 0, max: 2 * Math.PI, noNaN: true });

describe('invertPoint (σ_C(p) = c + r²(p−c)/|p−c|²)', () => {
  it('is an involution away from the centre', () => {
    fc.assert(
      fc.property(circle, point, (C, p) => {
        fc.pre(dist(p, C.c) > 1e-2);
        const back = invertPoint(C, invertPoint(C, p)!)!;
        expect(dist(back, p)).toBeLessThan(1e-9 * Math.max(1, len(p), C.r ** 2 / dist(p, C.c)));
      }),
      SEED,
    );
  });

  it('swaps inside and outside, fixes the circle, and keeps the ray from the centre', () => {
    fc.assert(
      fc.property(circle, angle, fc.double({ min: 0.05, max: 0.95, noNaN: true }), (C, t, f) => {
        const dir: Vec2 = [Math.cos(t), Math.sin(t)];
        const inside: Vec2 = [C.c[0] + f * C.r * dir[0], C.c[1] + f * C.r * dir[1]];
        const img = invertPoint(C, inside)!;
        expect(dist(img, C.c)).toBeCloseTo(C.r / f, 8); // |σ(p)−c| = r²/|p−c|
        expect(cross(sub(img, C.c), dir)).toBeCloseTo(0, 8);
        const onCircle: Vec2 = [C.c[0] + C.r * dir[0], C.c[1] + C.r * dir[1]];
        expect(dist(invertPoint(C, onCircle)!, onCircle)).toBeLessThan(1e-12 * (1 + len(onCircle)));
      }),
      SEED,
    );
  });

  it('has no image for the centre', () => {
    expect(invertPoint({ c: [1, 2], r: 3 }, [1, 2])).toBeNull();
  });

  it('matches a hand computation', () => {
    // unit circle: (2, 0) ↦ (0.5, 0); (0, 0.25) ↦ (0, 4)
    expect(invertPoint({ c: [0, 0], r: 1 }, [2, 0])).toEqual([0.5, 0]);
    expect(invertPoint({ c: [0, 0], r: 1 }, [0, 0.25])).toEqual([0, 4]);
    // c = (1, 1), r = 2: (2, 1) ↦ (1, 1) + 4·(1, 0) = (5, 1)
    expect(invertPoint({ c: [1, 1], r: 2 }, [2, 1])).toEqual([5, 1]);
  });
});

describe("invertCircle (C1 ↦ C1' of docs/math.md)", () => {
  it("matches the formula δ = |c1−c2|² − r1², k = r2²/δ, c1' = c2 + k(c1−c2), r1' = |k| r1", () => {
    const img = invertCircle({ c: [0, 0], r: 1 }, { c: [2, 0], r: 0.5 })!;
    // δ = 4 − 0.25 = 3.75, k = 1/3.75
    expect(img.c[0]).toBeCloseTo(2 / 3.75, 14);
    expect(img.c[1]).toBe(0);
    expect(img.r).toBeCloseTo(0.5 / 3.75, 14);
    // the images of the two x-axis points of C1 are the diameter of C1'
    expect(invertPoint({ c: [0, 0], r: 1 }, [1.5, 0])![0]).toBeCloseTo(img.c[0] + img.r, 14);
    expect(invertPoint({ c: [0, 0], r: 1 }, [2.5, 0])![0]).toBeCloseTo(img.c[0] - img.r, 14);
  });

  it("agrees with invertPoint: the images of points of C1 lie on C1'", () => {
    fc.assert(
      fc.property(circle, circle, fc.array(angle, { minLength: 1, maxLength: 6 }), (C2, C1, ts) => {
        const delta = dist(C1.c, C2.c) ** 2 - C1.r ** 2;
        fc.pre(Math.abs(delta) > 0.05 * Math.max(1, C1.r ** 2));
        const img = invertCircle(C2, C1)!;
        expect(img).not.toBeNull();
        for (const t of ts) {
          const q: Vec2 = [C1.c[0] + C1.r * Math.cos(t), C1.c[1] + C1.r * Math.sin(t)];
          const pq = invertPoint(C2, q);
          if (!pq || dist(q, C2.c) < 1e-3) continue;
          expect(Math.abs(dist(pq, img.c) - img.r)).toBeLessThan(1e-7 * Math.max(1, img.r, len(pq)));
        }
      }),
      SEED,
    );
  });

  it('gives null when C1 passes through the centre of C2 (its image is a line)', () => {
    expect(invertCircle({ c: [0, 0], r: 1 }, { c: [2, 0], r: 2 })).toBeNull();
    expect(invertCircle({ c: [1, 1], r: 3 }, { c: [1, 2], r: 1 })).toBeNull();
  });
});

describe('circleThrough3', () => {
  it('recovers the circle through three points of a random circle', () => {
    // three angles at least 0.3 rad apart keep the triangle well conditioned
    const angles = fc
      .tuple(
        angle,
        fc.double({ min: 0.3, max: 2.5, noNaN: true }),
        fc.double({ min: 0.3, max: 2.5, noNaN: true }),
      )
      .map(([t, u, v]) => [t, t + u, t + u + v]);
    fc.assert(
      fc.property(circle, angles, (C, ts) => {
        const [a, b, c] = ts.map((t): Vec2 => [C.c[0] + C.r * Math.cos(t), C.c[1] + C.r * Math.sin(t)]);
        const found = circleThrough3(a, b, c)!;
        expect(found).not.toBeNull();
        expect(dist(found.c, C.c)).toBeLessThan(1e-9 * Math.max(1, C.r, len(C.c)));
        expect(Math.abs(found.r - C.r)).toBeLessThan(1e-9 * Math.max(1, C.r));
        for (const p of [a, b, c])
          expect(Math.abs(dist(p, found.c) - found.r)).toBeLessThan(1e-9 * Math.max(1, C.r));
      }),
      SEED,
    );
  });

  it('finds the unit circle and a known circle', () => {
    const C = circleThrough3([1, 0], [0, 1], [-1, 0])!;
    expect(C.c[0]).toBeCloseTo(0, 14);
    expect(C.c[1]).toBeCloseTo(0, 14);
    expect(C.r).toBeCloseTo(1, 14);
    const D = circleThrough3([3, 2], [1, 4], [-1, 2])!; // centre (1, 2), r 2
    expect(D.c[0]).toBeCloseTo(1, 12);
    expect(D.c[1]).toBeCloseTo(2, 12);
    expect(D.r).toBeCloseTo(2, 12);
  });

  it('returns null for collinear or coinciding points', () => {
    expect(circleThrough3([0, 0], [1, 1], [2, 2])).toBeNull();
    expect(circleThrough3([-1, 0], [0, 0], [5, 0])).toBeNull();
    expect(circleThrough3([1, 1], [1, 1], [1, 1])).toBeNull();
    expect(circleThrough3([1, 1], [1, 1], [2, 3])).toBeNull();
    fc.assert(
      fc.property(point, point, fc.double({ min: -3, max: 3, noNaN: true }), (a, b, t) => {
        const c: Vec2 = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
        expect(circleThrough3(a, b, c)).toBeNull();
      }),
      SEED,
    );
  });
});

describe('lines and reflections', () => {
  it('the normal of a → b points to the left side', () => {
    expect(lineNormal({ a: [0, 0], b: [1, 0] })).toEqual([-0, 1]);
    const n = lineNormal({ a: [1, 1], b: [1, 5] }); // going up: left is −x
    expect(n[0]).toBeCloseTo(-1, 15);
    expect(n[1]).toBeCloseTo(0, 15);
    expect(signedDistance([0, 0], [0, 1], [3, -2])).toBe(-2);
  });

  it('reflection is an involution, fixes the line, and preserves distance to it', () => {
    fc.assert(
      fc.property(point, angle, point, (q, t, p) => {
        const n: Vec2 = [Math.cos(t), Math.sin(t)];
        const r = reflectPoint(q, n, p);
        expect(dist(reflectPoint(q, n, r), p)).toBeLessThan(1e-12 * (1 + len(p) + len(q)) * 10);
        expect(signedDistance(q, n, r)).toBeCloseTo(-signedDistance(q, n, p), 10);
        const onLine: Vec2 = [q[0] - 2 * n[1], q[1] + 2 * n[0]];
        expect(dist(reflectPoint(q, n, onLine), onLine)).toBeLessThan(1e-12 * (10 + len(q)));
      }),
      SEED,
    );
  });

  it('a line whose two points coincide is degenerate', () => {
    expect(isDegenerateLine({ a: [2, 3], b: [2, 3] })).toBe(true);
    expect(isDegenerateLine({ a: [2, 3], b: [2, 3.001] })).toBe(false);
  });
});
