import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { DiskRegion } from '../../../nodes/core/scene.ts';
import type { Circle, Vec2 } from '../../../nodes/core/values.ts';
import { invertCircle, invertPoint } from '../../../nodes/geometry/circle.ts';
import { classifyTwoCircle, twoCircleRegions } from '../../../nodes/geometry/mobius.ts';
import { dist } from '../../../nodes/geometry/vec.ts';

const SEED = { seed: 42, numRuns: 300 } as const;
const coord = fc.double({ min: -3, max: 3, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const circle = fc.record({
  c: point,
  r: fc.double({ min: 0.2, max: 3, noNaN: true }),
}) as fc.Arbitrary<Circle>;

/** g = σ_C2∘σ_C1 (σ_C1 applied first). */
const g = (c1: Circle, c2: Circle, p: Vec2) => invertPoint(c2, invertPoint(c1, p)!)!;
const inRegion = (R: DiskRegion, p: Vec2) => (R.outside ? dist(p, R.c) > R.r : dist(p, R.c) < R.r);

/** Crossing angle measured at an intersection point: the angle between the two radii there. */
function angleAtIntersection(c1: Circle, c2: Circle): number {
  const d = dist(c1.c, c2.c);
  const a = (d * d + c1.r * c1.r - c2.r * c2.r) / (2 * d); // along c1 → c2
  const h = Math.sqrt(c1.r * c1.r - a * a);
  const ux = (c2.c[0] - c1.c[0]) / d;
  const uy = (c2.c[1] - c1.c[1]) / d;
  const x: Vec2 = [c1.c[0] + a * ux - h * uy, c1.c[1] + a * uy + h * ux];
  const r1: Vec2 = [x[0] - c1.c[0], x[1] - c1.c[1]];
  const r2: Vec2 = [x[0] - c2.c[0], x[1] - c2.c[1]];
  return Math.acos((r1[0] * r2[0] + r1[1] * r2[1]) / (c1.r * c2.r));
}

describe('classifyTwoCircle', () => {
  it('disjoint circles are hyperbolic (trace formula)', () => {
    const cls = classifyTwoCircle({ c: [0, 0], r: 1 }, { c: [3, 0], r: 1 });
    expect(cls.type).toBe('hyperbolic');
    expect(cls.trace).toBeCloseTo(-7, 14); // (1 + 1 − 9)/1
    expect(cls.angle).toBeUndefined();
  });

  it('nested circles are hyperbolic', () => {
    const cls = classifyTwoCircle({ c: [0, 0], r: 1 }, { c: [0.3, 0], r: 2 });
    expect(cls.type).toBe('hyperbolic');
    expect(cls.trace).toBeCloseTo((1 + 4 - 0.09) / 2, 14);
  });

  it('tangent circles (outside and inside) are parabolic', () => {
    expect(classifyTwoCircle({ c: [0, 0], r: 1 }, { c: [2, 0], r: 1 }).type).toBe('parabolic');
    expect(classifyTwoCircle({ c: [0, 0], r: 2 }, { c: [1, 0], r: 1 }).type).toBe('parabolic');
    expect(classifyTwoCircle({ c: [0, 0], r: 1 }, { c: [0, 3], r: 2 }).type).toBe('parabolic');
  });

  it('crossing circles are elliptic with the crossing angle θ (cos θ = τ/2)', () => {
    // two unit circles at distance 1 cross at 60°: τ = 2 − 1 = 1
    const cls = classifyTwoCircle({ c: [0, 0], r: 1 }, { c: [1, 0], r: 1 });
    expect(cls.type).toBe('elliptic');
    expect(cls.trace).toBeCloseTo(1, 14);
    expect(cls.angle).toBeCloseTo(Math.PI / 3, 12);
    // orthogonal circles: d² = r1² + r2²
    const orth = classifyTwoCircle({ c: [0, 0], r: 1 }, { c: [2, 0], r: Math.sqrt(3) });
    expect(orth.angle).toBeCloseTo(Math.PI / 2, 12);
  });

  it('classifies random pairs as their geometry says, with τ from the formula', () => {
    fc.assert(
      fc.property(circle, circle, (c1, c2) => {
        const d = dist(c1.c, c2.c);
        const cls = classifyTwoCircle(c1, c2);
        expect(cls.trace).toBeCloseTo((c1.r ** 2 + c2.r ** 2 - d * d) / (c1.r * c2.r), 9);
        const margin = 1e-6;
        if (d > c1.r + c2.r + margin || d < Math.abs(c1.r - c2.r) - margin) {
          expect(cls.type).toBe('hyperbolic');
          expect(Math.abs(cls.trace)).toBeGreaterThan(2);
        } else if (d < c1.r + c2.r - margin && d > Math.abs(c1.r - c2.r) + margin) {
          expect(cls.type).toBe('elliptic');
          expect(cls.angle!).toBeCloseTo(angleAtIntersection(c1, c2), 5);
        }
      }),
      SEED,
    );
  });
});

describe('twoCircleRegions', () => {
  it("nested set-up (c2 inside C1, C1 inside C2): A = inside C1, B = outside C1'", () => {
    const c1 = { c: [0, 0] as Vec2, r: 1 };
    const c2 = { c: [0.3, 0] as Vec2, r: 2 };
    const R = twoCircleRegions(c1, c2);
    if (!R.ok) throw new Error(R.reason);
    expect(R.a).toEqual({ c: [0, 0], r: 1, outside: false });
    expect(R.b.outside).toBe(true);
    expect(R.c1Image).toEqual(invertCircle(c2, c1));
    expect(R.b.c).toEqual(R.c1Image.c);
    expect(R.b.r).toBe(R.c1Image.r);
    // the tile (outside C1, inside C1') is not empty: C1 lies strictly inside C1'
    expect(dist(R.c1Image.c, c1.c) + c1.r).toBeLessThan(R.c1Image.r);
    expect(R.tiling).toBe(true);
  });

  it("inner set-up (C2 inside C1): the roles flip, A = outside C1, B = inside C1'", () => {
    const R = twoCircleRegions({ c: [0, 0], r: 2 }, { c: [0.3, 0], r: 0.5 });
    if (!R.ok) throw new Error(R.reason);
    expect(R.a.outside).toBe(true);
    expect(R.a.r).toBe(2);
    expect(R.b.outside).toBe(false);
    // tile = inside C1 and outside C1': C1' is a small circle inside C1
    expect(dist(R.b.c, [0, 0]) + R.b.r).toBeLessThan(2);
  });

  it("Schottky set-up (disjoint circles): A = inside C1, B = inside C1'", () => {
    const R = twoCircleRegions({ c: [-2, 0], r: 1 }, { c: [2, 0], r: 1 });
    if (!R.ok) throw new Error(R.reason);
    expect(R.a).toEqual({ c: [-2, 0], r: 1, outside: false });
    expect(R.b.outside).toBe(false);
    // C1' = σ_C2(C1) lies inside C2
    expect(dist(R.b.c, [2, 0]) + R.b.r).toBeLessThan(1);
  });

  it("concentric circles: B = outside C1' (g fixes ∞)", () => {
    const R = twoCircleRegions({ c: [0, 0], r: 1 }, { c: [0, 0], r: 2 });
    if (!R.ok) throw new Error(R.reason);
    expect(R.a.outside).toBe(false);
    expect(R.b).toEqual({ c: [0, 0], r: 4, outside: true });
  });

  it('rejects identical circles and C1 through the centre of C2', () => {
    expect(twoCircleRegions({ c: [1, 1], r: 1 }, { c: [1, 1], r: 1 }).ok).toBe(false);
    const through = twoCircleRegions({ c: [1, 0], r: 1 }, { c: [0, 0], r: 3 });
    expect(through.ok).toBe(false);
    if (!through.ok) expect(through.reason).toMatch(/line/);
  });

  it('flags elliptic pairs whose angle is not π/n as not a tiling', () => {
    const at = (theta: number) => {
      // radii 1 and 1.5 cross at θ when d² = 1 + 2.25 − 3 cos θ (law of cosines)
      const d = Math.sqrt(3.25 - 3 * Math.cos(theta));
      const R = twoCircleRegions({ c: [0, 0], r: 1 }, { c: [d, 0], r: 1.5 });
      if (!R.ok) throw new Error(R.reason);
      return R.tiling;
    };
    expect(at(Math.PI / 3)).toBe(true);
    expect(at(Math.PI / 4)).toBe(true);
    expect(at(Math.PI - Math.PI / 5)).toBe(true);
    expect(at(1)).toBe(false);
    expect(at(0.6)).toBe(false);
    expect(at(Math.PI / 2)).toBe(true);
  });

  it('g maps the complement of A into B (sample points, random circle pairs)', () => {
    fc.assert(
      fc.property(circle, circle, point, (c1, c2, x) => {
        const R = twoCircleRegions(c1, c2);
        fc.pre(R.ok);
        if (!R.ok) return;
        // stay clear of C1 (mapped onto the boundary C1'), c1 (mapped to ∞ when A = outside) and c2
        fc.pre(Math.abs(dist(x, c1.c) - c1.r) > 1e-3 && dist(x, c1.c) > 1e-3);
        fc.pre(!inRegion(R.a, x));
        const y = g(c1, c2, x);
        fc.pre(Math.abs(dist(y, R.b.c) - R.b.r) > 1e-9 * Math.max(1, R.b.r));
        expect(inRegion(R.b, y)).toBe(true);
      }),
      { seed: 42, numRuns: 600 },
    );
  });

  it('g maps A onto the outside of B (so g⁻¹ undoes the step)', () => {
    fc.assert(
      fc.property(circle, circle, point, (c1, c2, x) => {
        const R = twoCircleRegions(c1, c2);
        fc.pre(R.ok);
        if (!R.ok) return;
        fc.pre(inRegion(R.a, x) && dist(x, c1.c) > 1e-3 && Math.abs(dist(x, c1.c) - c1.r) > 1e-3);
        const y = g(c1, c2, x);
        fc.pre(Math.abs(dist(y, R.b.c) - R.b.r) > 1e-9 * Math.max(1, R.b.r));
        expect(inRegion(R.b, y)).toBe(false);
      }),
      { seed: 42, numRuns: 600 },
    );
  });
});
