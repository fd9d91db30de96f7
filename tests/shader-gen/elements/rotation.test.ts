import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { RotationElement } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { add, rotate, sub } from '../../../nodes/geometry/vec.ts';
import { elementRecord } from '../../../shader-gen/elements/index.ts';
import { foldStepwise, foldWithKind, nearInteger } from './fold-support.ts';

const SEED = { seed: 42, numRuns: 400 } as const;
const coord = fc.double({ min: -5, max: 5, noNaN: true });
const point = fc.tuple(coord, coord) as fc.Arbitrary<Vec2>;
const rotationElement = fc
  .record({
    c: fc.tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true })),
    start: fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
    order: fc.integer({ min: 2, max: 24 }),
  })
  .map(
    ({ c, start, order }): RotationElement => ({
      kind: 'rotation',
      nodeId: 'n',
      c,
      b1: [Math.cos(start), Math.sin(start)],
      order,
    }),
  );

/** arg of p − c measured counter-clockwise from b1, in [0, 2π). */
function argFrom(e: RotationElement, p: Vec2): number {
  const d = sub(p, e.c);
  const a = Math.atan2(d[1], d[0]) - Math.atan2(e.b1[1], e.b1[0]);
  return ((a % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
}

describe('rotation (closed form)', () => {
  it('folds like "rotate by −θ while outside the wedge"', () => {
    fc.assert(
      fc.property(rotationElement, point, (e, p) => {
        const theta = (2 * Math.PI) / e.order;
        fc.pre(!nearInteger(argFrom(e, p) / theta, 1e-6) && Math.hypot(...sub(p, e.c)) > 1e-6);
        const single = (x: Vec2) =>
          argFrom(e, x) < theta ? null : { p: add(e.c, rotate(sub(x, e.c), -theta)), s: 1 };
        const fast = foldWithKind(e, p);
        const slow = foldStepwise(p, single);
        expect(fast.depth).toBe(slow.depth);
        expect(fast.depth).toBeLessThan(e.order);
        expect(fast.p[0]).toBeCloseTo(slow.p[0], 9);
        expect(fast.p[1]).toBeCloseTo(slow.p[1], 9);
        expect(fast.calls).toBeLessThanOrEqual(1);
        expect(fast.s).toBe(1);
      }),
      SEED,
    );
  });

  it('keeps the wedge from b1 counter-clockwise by 2π/k; the centre is in the tile', () => {
    const e: RotationElement = { kind: 'rotation', nodeId: 'n', c: [1, 1], b1: [0, 1], order: 4 };
    const k = elementRecord(e).cpu;
    expect(k.inside(e, 0.5, 1.5)).toBe(false); // arg 45° from b1 (up): inside the 90° wedge
    expect(k.inside(e, 1.5, 1.5)).toBe(true); // clockwise of b1: the last wedge
    expect(k.inside(e, 1, 1)).toBe(false);
    const r = foldWithKind(e, [1.5, 1.5]); // 3 quarter turns back
    expect(r.depth).toBe(3);
    expect(r.p[0]).toBeCloseTo(0.5, 12);
    expect(r.p[1]).toBeCloseTo(1.5, 12);
    expect(k.boundaryDistance(e, 0.5, 1.5)).toBeCloseTo(0.5, 12);
  });
});
