/** The IIS loop of docs/math.md through `interpret`, on small scenes whose answers are known by hand. */
import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../nodes/core/values.ts';
import { interpret } from '../../shader-gen/interpret.ts';
import { inv, rectangle, scene } from './interpret-scenes.ts';

describe('interpret', () => {
  it('an empty scene: every point is in the tile', () => {
    expect(interpret(scene([]), [3, -4])).toEqual({ depth: 0, final: [3, -4], escaped: true, scale: 1 });
  });

  it('one inversion: depth 1, σ(p), scale r²/|p−c|²', () => {
    const r = interpret(scene([inv([0, 0], 2)]), [1, 0]);
    expect(r).toEqual({ depth: 1, final: [4, 0], escaped: true, scale: 4 });
    expect(interpret(scene([inv([0, 0], 2)]), [3, 0]).depth).toBe(0);
    expect(interpret(scene([inv([0, 0], 2)]), [2, 0]).depth).toBe(0); // the boundary is in the tile (strict inside)
  });

  it('the scale is the product of the conformal factors along the path', () => {
    // two disjoint inversions; the paths below are worked out by hand
    const A = inv([0, 0], 1);
    const B = inv([3, 0], 1);
    // p = (0.5, 0): A → (2, 0), factor 4; B: |(2,0)−(3,0)| = 1, on the circle: not inside → stop
    const r = interpret(scene([A, B]), [0.5, 0]);
    expect(r).toMatchObject({ depth: 1, final: [2, 0], scale: 4, escaped: true });
    // p = (2.5, 0): B → 3 + 1/(−0.5) = (1, 0) factor 4; A: on circle, stop
    expect(interpret(scene([A, B]), [2.5, 0])).toMatchObject({ depth: 1, final: [1, 0], scale: 4 });
    // p = (2.75, 0): B → 3 − 4 = (−1, 0), on A: stop, factor 16
    expect(interpret(scene([A, B]), [2.75, 0])).toMatchObject({ depth: 1, final: [-1, 0], scale: 16 });
    // p = (2.8, 0): B → 3 − 5 = (−2, 0), factor 25: outside both
    const q = interpret(scene([A, B]), [2.8, 0]);
    expect(q.final[0]).toBeCloseTo(-2, 12);
    expect(q.scale).toBeCloseTo(25, 10);
    // p = (2.5625, 0): B → 3 − 16/7 = 5/7, factor 256/49; A: 5/7 ↦ 7/5, factor 49/25; then outside both
    const t = interpret(scene([A, B]), [2.5625, 0]);
    expect(t.depth).toBe(2);
    expect(t.final[0]).toBeCloseTo(1.4, 12);
    expect(t.scale).toBeCloseTo(256 / 25, 10);
    expect(t.escaped).toBe(true);
  });

  it('tests elements in graph order: the first whose inside holds p acts', () => {
    const A = inv([0, 0], 1);
    const B = inv([0.5, 0], 1);
    // (0.25, 0) is inside both
    expect(interpret(scene([A, B]), [0.25, 0]).final).toEqual([4, 0]);
    expect(interpret(scene([B, A]), [0.25, 0]).final).toEqual([-3.5, 0]);
  });

  it('stops at maxIterations: not escaped, depth = maxIterations', () => {
    const rect = rectangle(1, 1);
    const p: Vec2 = [10.5, 0.5]; // needs exactly 10 reflections
    expect(interpret(scene(rect, 100), p)).toMatchObject({ depth: 10, escaped: true });
    expect(interpret(scene(rect, 10), p)).toMatchObject({ depth: 10, escaped: true });
    expect(interpret(scene(rect, 9), p)).toMatchObject({ depth: 9, escaped: false });
    expect(interpret(scene(rect, 1), p)).toMatchObject({ depth: 1, escaped: false });
  });

  it('a point on the limit set keeps moving (a Schottky pair of inversions)', () => {
    // x* = −√3 is the fixed point of σ_A∘σ_B in A: the IIS bounces A, B, A, B, … from it (until
    // float rounding, which this repelling orbit amplifies, throws it off after about a dozen steps).
    const A = inv([-2, 0], 1);
    const B = inv([2, 0], 1);
    const r = interpret(scene([A, B], 8), [-Math.sqrt(3), 0]);
    expect(r).toMatchObject({ escaped: false, depth: 8 });
    expect(r.final[0]).toBeCloseTo(-Math.sqrt(3), 4);
  });
});
