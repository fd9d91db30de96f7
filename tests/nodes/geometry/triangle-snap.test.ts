import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../../nodes/core/values.ts';
import {
  nearestOrders,
  type SnapLine,
  snapTriangle,
  type TriangleSnapInput,
  triangleAngles,
  triangleCorners,
} from '../../../nodes/geometry/triangle-snap.ts';

const SEED = { seed: 23, numRuns: 200 } as const;
const TOL = 1e-4;
const deg = (d: number) => (d * Math.PI) / 180;

/** Lines AB, AC, BC through free points A, B, C (the classroom wiring): line k opposite corner k. */
const classroom = (a: Vec2, b: Vec2, c: Vec2, free = [true, true, true]): TriangleSnapInput => ({
  lines: [{ points: ['B', 'C'] }, { points: ['A', 'C'] }, { points: ['A', 'B'] }] as [
    SnapLine,
    SnapLine,
    SnapLine,
  ],
  points: [
    { id: 'A', at: a, free: free[0] },
    { id: 'B', at: b, free: free[1] },
    { id: 'C', at: c, free: free[2] },
  ],
  tolerance: TOL,
});

/** The triangle's angles after applying the snap's moves to the input. */
function anglesAfter(input: TriangleSnapInput, moves: readonly { id: string; to: Vec2 }[]) {
  const pos = new Map(input.points.map((p) => [p.id, p.at]));
  for (const m of moves) pos.set(m.id, m.to);
  const corners = triangleCorners(input.lines.map((l) => [pos.get(l.points[0])!, pos.get(l.points[1])!]));
  return triangleAngles(corners!);
}

const isPiOverN = (a: number) => Math.abs(a - Math.PI / Math.round(Math.PI / a)) < 1e-9;

describe('triangle snap', () => {
  it('the issue #23 triangle: keeps A and B, moves C back to (0, √3), all of (2, 3, 6) at once', () => {
    const input = classroom([0, 0], [1, 0], [0, 1.5]);
    const snap = snapTriangle(input)!;
    expect(snap.orders).toEqual([2, 3, 6]);
    expect(snap.changedExact).toEqual([]);
    expect(snap.moves).toHaveLength(1);
    expect(snap.moves[0].id).toBe('C');
    expect(snap.moves[0].to[0]).toBeCloseTo(0, 12);
    expect(snap.moves[0].to[1]).toBeCloseTo(Math.sqrt(3), 12);
    const after = anglesAfter(input, snap.moves);
    expect(after[0]).toBeCloseTo(Math.PI / 2, 12);
    expect(after[1]).toBeCloseTo(Math.PI / 3, 12);
    expect(after[2]).toBeCloseTo(Math.PI / 6, 12);
  });

  it('a corner already at π/n is kept even when another triple is nearer in total', () => {
    // 90°, 50°, 40°: (2, 4, 4) is 10° away at two corners, (2, 3, 6) 10° + 10°; both keep the 90°.
    expect(nearestOrders([deg(90), deg(50), deg(40)], TOL).orders).toEqual([2, 4, 4]);
    // 60° exact at A: (3, 3, 3) keeps it although (2, 3, 6) with 90° at B would be nearer.
    expect(nearestOrders([deg(60), deg(84), deg(36)], TOL).orders).toEqual([3, 2, 6]);
    expect(nearestOrders([deg(60), deg(70), deg(50)], TOL).orders).toEqual([3, 3, 3]);
  });

  it('π/3 and π/4 exact leave 5π/12: no triple keeps both, the nearest changes one and says so', () => {
    const snap = nearestOrders([deg(60), deg(45), deg(75)], TOL);
    expect(snap.changedExact).toHaveLength(1);
    expect(snap.orders.map((n) => 1 / n).reduce((a, b) => a + b)).toBeCloseTo(1, 12);
  });

  it('a fixed point is never moved: the side through it is kept instead', () => {
    const input = classroom([0, 0], [1, 0], [0, 1.5], [true, true, false]);
    const snap = snapTriangle(input)!;
    expect(snap.moves.map((m) => m.id)).not.toContain('C');
    expect(anglesAfter(input, snap.moves).every(isPiOverN)).toBe(true);
    expect(snapTriangle(classroom([0, 0], [1, 0], [0, 1.5], [false, false, false]))).toBeNull();
  });

  it('lines through points that are not corners: each point keeps its distance from the pivot', () => {
    // Mirrors y = 0 (through P, Q), x = 0 (through R, S) and a slanted line through T, U.
    const input: TriangleSnapInput = {
      lines: [{ points: ['T', 'U'] }, { points: ['R', 'S'] }, { points: ['P', 'Q'] }],
      points: [
        { id: 'P', at: [-1, 0], free: true },
        { id: 'Q', at: [3, 0], free: true },
        { id: 'R', at: [0, -1], free: true },
        { id: 'S', at: [0, 3], free: true },
        { id: 'T', at: [-0.5, 2.5], free: true },
        { id: 'U', at: [1.5, -0.5], free: true },
      ],
      tolerance: TOL,
    };
    const snap = snapTriangle(input)!;
    expect(snap.moves.length).toBeGreaterThan(0);
    expect(anglesAfter(input, snap.moves).every(isPiOverN)).toBe(true);
    expect(
      triangleAngles(
        triangleCorners([
          [
            [-0.5, 2.5],
            [1.5, -0.5],
          ],
          [
            [0, -1],
            [0, 3],
          ],
          [
            [-1, 0],
            [3, 0],
          ],
        ])!,
      )[0],
    ).toBeCloseTo(Math.PI / 2);
  });

  it('property: after one snap every angle is π/n within 1e-9, and exact angles stay', () => {
    const coord = fc.double({ min: -3, max: 3, noNaN: true });
    fc.assert(
      fc.property(coord, coord, coord, coord, coord, coord, (ax, ay, bx, by, cx, cy) => {
        const input = classroom([ax, ay], [bx, by], [cx, cy]);
        const corners = triangleCorners([
          [input.points[1].at, input.points[2].at],
          [input.points[0].at, input.points[2].at],
          [input.points[0].at, input.points[1].at],
        ]);
        // Slivers (an angle under 1°) are not triangles a lesson uses; they snap, but far.
        if (!corners || triangleAngles(corners).some((a) => a < deg(1))) return;
        const snap = snapTriangle(input)!;
        expect(snap).not.toBeNull();
        expect(snap.moves.length).toBeLessThanOrEqual(1);
        const after = anglesAfter(input, snap.moves);
        for (const [k, a] of after.entries())
          expect(Math.abs(a - Math.PI / snap.orders[k])).toBeLessThan(1e-9);
      }),
      SEED,
    );
  });

  it('property: a triangle with one exact corner, the others off, snaps keeping that corner', () => {
    const orders = fc.constantFrom<[number, number]>([2, 3], [2, 4], [3, 3], [4, 2], [3, 2], [6, 2], [3, 6]);
    fc.assert(
      fc.property(
        orders,
        fc.double({ min: -0.2, max: 0.2, noNaN: true }),
        fc.double({ min: 0.2, max: 5, noNaN: true }),
        fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
        ([p, q], wobble, size, turn) => {
          // A exact at π/p; B at π/q + wobble (so C is off by −wobble unless wobble is tiny).
          const b: Vec2 = [size * Math.cos(turn), size * Math.sin(turn)];
          const ay = Math.PI / p;
          const by = Math.PI / q + wobble;
          if (ay + by > Math.PI - 0.05) return;
          const c: Vec2 = [
            ((size * Math.sin(by)) / Math.sin(ay + by)) * Math.cos(turn + ay),
            ((size * Math.sin(by)) / Math.sin(ay + by)) * Math.sin(turn + ay),
          ];
          const input = classroom([0, 0], b, c);
          const snap = snapTriangle(input)!;
          expect(snap.changedExact).toEqual([]);
          const after = anglesAfter(input, snap.moves);
          expect(Math.abs(after[0] - ay)).toBeLessThan(1e-12);
          for (const [k, a] of after.entries())
            expect(Math.abs(a - Math.PI / snap.orders[k])).toBeLessThan(1e-9);
        },
      ),
      SEED,
    );
  });
});
