import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { cross, sub } from '../../../nodes/geometry/vec.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

const SEED = { seed: 42, numRuns: 300 } as const;
const small = fc.double({ min: -2, max: 2, noNaN: true });
const vec = fc.tuple(small, small) as fc.Arbitrary<Vec2>;

/** Coordinates (s, t) of p − q in the basis u, v (Cramer's rule). */
function coords(q: Vec2, u: Vec2, v: Vec2, p: Vec2): [number, number] {
  const d = sub(p, q);
  const det = cross(u, v);
  return [cross(d, v) / det, cross(u, d) / det];
}

describe('lattice node', () => {
  it('defaults: a hexagonal lattice, two translation elements', () => {
    const r = checkDefaults('lattice');
    expect(r.readout).toBe('|u| = 1, |v| = 1, angle 60°');
    expect((r.outputs!.elements as SceneElement[]).map((e) => e.kind)).toEqual([
      'translation',
      'translation',
    ]);
  });

  it('folds every point into the parallelogram q + s·u + t·v, 0 ≤ s, t < 1, in |a| + |b| steps', () => {
    const basis = fc
      .record({
        l1: fc.double({ min: 0.3, max: 2, noNaN: true }),
        l2: fc.double({ min: 0.3, max: 2, noNaN: true }),
        a: fc.double({ min: -Math.PI, max: Math.PI, noNaN: true }),
        b: fc.double({ min: 0.3, max: Math.PI - 0.3, noNaN: true }),
      })
      .map(({ l1, l2, a, b }): [Vec2, Vec2] => [
        [l1 * Math.cos(a), l1 * Math.sin(a)],
        [l2 * Math.cos(a + b), l2 * Math.sin(a + b)],
      ]);
    // A whole part and a fraction kept off 0 and 1 (points on a tile edge may fold either way).
    const coordinate = fc
      .tuple(fc.integer({ min: -6, max: 5 }), fc.double({ min: 1e-6, max: 1 - 1e-6, noNaN: true }))
      .map(([k, f]) => k + f);
    fc.assert(
      fc.property(vec, basis, coordinate, coordinate, (q, [u, v], s0, t0) => {
        const r = evalNode('lattice', {
          origin: q,
          u: [q[0] + u[0], q[1] + u[1]],
          v: [q[0] + v[0], q[1] + v[1]],
        });
        const scene = { elements: r.outputs!.elements as SceneElement[], maxIterations: 1000 };
        const p: Vec2 = [q[0] + s0 * u[0] + t0 * v[0], q[1] + s0 * u[1] + t0 * v[1]];
        const res = interpret(scene, p);
        const [a, b] = [Math.floor(s0), Math.floor(t0)];
        expect(res.escaped).toBe(true);
        expect(res.depth).toBe(Math.abs(a) + Math.abs(b));
        const [s1, t1] = coords(q, u, v, res.final);
        expect(s1).toBeCloseTo(s0 - a, 8);
        expect(t1).toBeCloseTo(t0 - b, 8);
      }),
      SEED,
    );
  });

  it('collinear corners are an error; the corners are draggable', () => {
    expect(codes(evalNode('lattice', { origin: [0, 0], u: [1, 1], v: [2, 2] }))).toEqual(['KF303']);
    const def = defOf('lattice');
    const r = evalNode('lattice');
    expect(def.handles!(r.ctx!, r.outputs!).map((h) => h.handle)).toEqual(['origin', 'u', 'v']);
    expect(def.overlay!(r.ctx!, r.outputs!)).toHaveLength(4);
  });
});
