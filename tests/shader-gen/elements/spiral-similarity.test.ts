import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { SpiralSimilarityElement } from '../../../nodes/core/scene.ts';
import type { Circle, Vec2 } from '../../../nodes/core/values.ts';
import { invertPoint, reflectPoint } from '../../../nodes/geometry/circle.ts';
import { dist } from '../../../nodes/geometry/vec.ts';
import { elementRecord } from '../../../shader-gen/elements/index.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { foldStepwise, foldWithKind, nearInteger } from './fold-support.ts';

const SEED = { seed: 42, numRuns: 400 } as const;
const spiral = fc
  .record({
    c: fc.tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true })),
    r1: fc.double({ min: 0.2, max: 1, noNaN: true }),
    ratio: fc.double({ min: 1.2, max: 2, noNaN: true }),
    angle: fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
  })
  .map(
    ({ c, r1, ratio, angle }): SpiralSimilarityElement => ({
      kind: 'spiral-similarity',
      nodeId: 'n',
      c,
      r1,
      r2: r1 * ratio,
      angle,
    }),
  );
const polar = fc.record({
  logRadius: fc.double({ min: -4, max: 4, noNaN: true }),
  t: fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
});

/**
 * One step as docs/math.md defines it, from mirrors: g = σ_r2 ∘ σ_r1 ∘ ρ_φ ∘ ρ_0 (reflect in the line at
 * angle 0 through c, then in the line at angle φ, then invert in r1, then in r2); g⁻¹ in reverse.
 */
function mirrorsStep(e: SpiralSimilarityElement) {
  const line = (a: number): [Vec2, Vec2] => [e.c, [-Math.sin(a), Math.cos(a)]];
  const c1: Circle = { c: e.c, r: e.r1 };
  const c2: Circle = { c: e.c, r: e.r2 };
  const lambda = (e.r2 / e.r1) ** 2;
  const g = (p: Vec2) =>
    invertPoint(c2, invertPoint(c1, reflectPoint(...line(e.angle), reflectPoint(...line(0), p)))!)!;
  const gInv = (p: Vec2) =>
    reflectPoint(...line(0), reflectPoint(...line(e.angle), invertPoint(c1, invertPoint(c2, p)!)!));
  return (p: Vec2) => {
    const rho = dist(p, e.c);
    if (rho < e.r1) return { p: g(p), s: lambda };
    if (rho >= (e.r2 * e.r2) / e.r1) return { p: gInv(p), s: 1 / lambda };
    return null;
  };
}

describe('spiral similarity (closed form)', () => {
  it('folds like the mirror composition applied step by step (point, depth and scale)', () => {
    fc.assert(
      fc.property(spiral, polar, (e, { logRadius, t }) => {
        const lambda = (e.r2 / e.r1) ** 2;
        const rho = e.r1 * Math.exp(logRadius);
        fc.pre(!nearInteger(Math.log(rho / e.r1) / Math.log(lambda), 1e-6));
        const p: Vec2 = [e.c[0] + rho * Math.cos(t), e.c[1] + rho * Math.sin(t)];
        const fast = foldWithKind(e, p);
        const slow = foldStepwise(p, mirrorsStep(e));
        expect(fast.depth).toBe(slow.depth);
        expect(fast.calls).toBeLessThanOrEqual(1);
        expect(fast.p[0]).toBeCloseTo(slow.p[0], 7);
        expect(fast.p[1]).toBeCloseTo(slow.p[1], 7);
        expect(fast.s / slow.s).toBeCloseTo(1, 9);
      }),
      SEED,
    );
  });

  it('the annulus r1 ≤ |p − c| < r2²/r1 is the tile; the centre never escapes', () => {
    const e: SpiralSimilarityElement = {
      kind: 'spiral-similarity',
      nodeId: 'n',
      c: [0, 0],
      r1: 1,
      r2: 2,
      angle: 0,
    };
    const k = elementRecord(e).cpu;
    expect(k.inside(e, 1, 0)).toBe(false);
    expect(k.inside(e, 3.99, 0)).toBe(false);
    expect(k.inside(e, 4, 0)).toBe(true);
    expect(k.inside(e, 0.99, 0)).toBe(true);
    const r = foldWithKind(e, [0.1, 0]); // 0.1 · 4² = 1.6 in the annulus after two steps
    expect(r.depth).toBe(2);
    expect(r.p[0]).toBeCloseTo(1.6, 12);
    expect(r.s).toBeCloseTo(16, 12);
    const centre = interpret({ elements: [e], maxIterations: 50 }, [0, 0]);
    expect(centre.escaped).toBe(false);
    expect(centre.depth).toBe(50);
  });
});
