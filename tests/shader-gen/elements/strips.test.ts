import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type {
  GlideReflectionElement,
  ParallelMirrorsElement,
  StripData,
  TranslationElement,
} from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { reflectPoint } from '../../../nodes/geometry/circle.ts';
import { add, dot, perp, scale, sub } from '../../../nodes/geometry/vec.ts';
import { elementRecord } from '../../../shader-gen/elements/index.ts';
import { foldStepwise, foldWithKind, nearInteger } from './fold-support.ts';

const SEED = { seed: 42, numRuns: 400 } as const;
const coord = fc.double({ min: -20, max: 20, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const strip = fc.record({
  q: fc.tuple(fc.double({ min: -2, max: 2, noNaN: true }), fc.double({ min: -2, max: 2, noNaN: true })),
  angle: fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }),
  period: fc.double({ min: 0.3, max: 3, noNaN: true }),
});
const toStrip = (s: { q: [number, number]; angle: number; period: number }): StripData => ({
  q: s.q,
  n: [Math.cos(s.angle), Math.sin(s.angle)],
  period: s.period,
});
const height = (e: StripData, p: Vec2) => dot(sub(p, e.q), e.n);
const inTile = (e: StripData, p: Vec2) => height(e, p) >= 0 && height(e, p) < e.period;

/** The single steps of docs/math.md, one period or one mirror at a time. */
const singles = {
  translation: (e: StripData) => (p: Vec2) =>
    inTile(e, p) ? null : { p: add(p, scale(e.n, height(e, p) < 0 ? e.period : -e.period)), s: 1 },
  'parallel-mirrors': (e: StripData) => (p: Vec2) => {
    if (inTile(e, p)) return null;
    const below = height(e, p) < 0;
    const q = below ? e.q : add(e.q, scale(e.n, e.period));
    return { p: reflectPoint(q, e.n, p), s: 1 };
  },
  // g = reflect in the axis after translating by D·n; g⁻¹ = translate back after reflecting.
  'glide-reflection': (e: StripData) => (p: Vec2) => {
    if (inTile(e, p)) return null;
    const axis = (x: Vec2) => reflectPoint(e.q, perp(e.n), x);
    return {
      p: height(e, p) < 0 ? axis(add(p, scale(e.n, e.period))) : sub(axis(p), scale(e.n, e.period)),
      s: 1,
    };
  },
} as const;

for (const kind of ['translation', 'parallel-mirrors', 'glide-reflection'] as const) {
  describe(`${kind} (closed form)`, () => {
    const element = (s: StripData) =>
      ({ kind, nodeId: 'n', ...s }) as TranslationElement | ParallelMirrorsElement | GlideReflectionElement;

    it('folds to the same point and depth as the stepwise loop, in one call', () => {
      fc.assert(
        fc.property(strip, point, (raw, p) => {
          const e = toStrip(raw);
          fc.pre(!nearInteger(height(e, p) / e.period, 1e-6));
          const fast = foldWithKind(element(e), p);
          const slow = foldStepwise(p, singles[kind](e));
          expect(fast.depth).toBe(slow.depth);
          expect(fast.p[0]).toBeCloseTo(slow.p[0], 9);
          expect(fast.p[1]).toBeCloseTo(slow.p[1], 9);
          expect(fast.s).toBe(1);
          expect(fast.calls).toBeLessThanOrEqual(1);
          expect(inTile(e, fast.p)).toBe(true);
        }),
        SEED,
      );
    });

    it('inside is exactly "step would apply", and the tile is half-open 0 ≤ h < D', () => {
      const e = element({ q: [0, 0], n: [1, 0], period: 1 });
      const k = elementRecord(e).cpu;
      expect(k.inside(e, 0, 5)).toBe(false); // on the first edge: in the tile
      expect(k.inside(e, 1, 5)).toBe(true); // on the second edge: the next tile
      expect(k.inside(e, -1e-9, 0)).toBe(true);
      expect(k.inside(e, 0.999, 0)).toBe(false);
      expect(k.boundaryDistance(e, 0.25, 3)).toBeCloseTo(0.25, 12);
      expect(k.boundaryDistance(e, 0.9, 3)).toBeCloseTo(0.1, 12);
    });

    it('counts |k| steps for a point k periods away', () => {
      const e = element({ q: [0, 0], n: [0, 1], period: 0.5 });
      expect(foldWithKind(e, [0.1, 3.2]).depth).toBe(6);
      expect(foldWithKind(e, [0.1, -3.2]).depth).toBe(7);
    });
  });
}

describe('the strip kinds differ as they should', () => {
  const s: StripData = { q: [0, 0], n: [1, 0], period: 1 };
  const p: Vec2 = [1.25, 0.3];
  it('translation shifts, parallel mirrors reflect, glide shifts and flips', () => {
    expect(foldWithKind({ kind: 'translation', nodeId: 'n', ...s }, p).p).toEqual([0.25, 0.3]);
    const m = foldWithKind({ kind: 'parallel-mirrors', nodeId: 'n', ...s }, p).p;
    expect(m[0]).toBeCloseTo(0.75, 12);
    expect(m[1]).toBeCloseTo(0.3, 12);
    const g = foldWithKind({ kind: 'glide-reflection', nodeId: 'n', ...s }, p).p;
    expect(g[0]).toBeCloseTo(0.25, 12);
    expect(g[1]).toBeCloseTo(-0.3, 12);
  });
});
