import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { topologicalOrder } from '../../../nodes/graph/topo.ts';
import { shuffled } from '../support/doc.ts';

describe('topologicalOrder', () => {
  it('orders dependencies first and breaks ties by id', () => {
    const r = topologicalOrder(
      ['z', 'b', 'a', 'c'],
      [
        { from: 'z', to: 'c' },
        { from: 'a', to: 'c' },
      ],
    );
    expect(r.order).toEqual(['a', 'b', 'z', 'c']);
    expect(r.cycles).toEqual([]);
    expect(r.blocked.size).toBe(0);
  });

  it('ties are broken by code-unit order of ids, also for nodes freed later', () => {
    // root frees x3, x1, x2 at once; B (ready from the start) comes before them, a after
    const r = topologicalOrder(
      ['root', 'x3', 'x1', 'x2', 'B', 'a'],
      [
        { from: 'root', to: 'x3' },
        { from: 'root', to: 'x1' },
        { from: 'root', to: 'x2' },
      ],
    );
    expect(r.order).toEqual(['B', 'a', 'root', 'x1', 'x2', 'x3']);
  });

  it('gives the same order for any shuffle of the node and edge arrays', () => {
    // random DAGs: edges only from a lower to a higher index, ids unrelated to index
    const dag = fc
      .integer({ min: 1, max: 25 })
      .chain((n) =>
        fc.tuple(
          fc.uniqueArray(fc.string({ minLength: 1, maxLength: 4 }), { minLength: n, maxLength: n }),
          fc.array(fc.tuple(fc.nat(n - 1), fc.nat(n - 1)), { maxLength: 60 }),
          fc.integer(),
        ),
      );
    fc.assert(
      fc.property(dag, ([ids, pairs, seed]) => {
        const edges = pairs.filter(([i, j]) => i < j).map(([i, j]) => ({ from: ids[i], to: ids[j] }));
        const a = topologicalOrder(ids, edges);
        const b = topologicalOrder(shuffled(ids, seed), shuffled(edges, seed + 1));
        expect(b.order).toEqual(a.order);
        expect(a.order).toHaveLength(ids.length);
        const pos = new Map(a.order.map((id, i) => [id, i]));
        for (const e of edges) expect(pos.get(e.from)!).toBeLessThan(pos.get(e.to)!);
      }),
      { seed: 42, numRuns: 200 },
    );
  });

  it('reports a cycle with its path and blocks what is downstream', () => {
    const r = topologicalOrder(
      ['a', 'b', 'c', 'd', 'e'],
      [
        { from: 'a', to: 'b' },
        { from: 'b', to: 'c' },
        { from: 'c', to: 'b' },
        { from: 'c', to: 'd' },
      ],
    );
    expect(r.order).toEqual(['a', 'e']);
    expect([...r.blocked].sort()).toEqual(['b', 'c', 'd']);
    expect(r.cycles).toEqual([['b', 'c', 'b']]);
  });

  it('finds one cycle per knot, each closed (first id repeated at the end)', () => {
    const r = topologicalOrder(
      ['p', 'q', 'r', 'x', 'y'],
      [
        { from: 'p', to: 'q' },
        { from: 'q', to: 'r' },
        { from: 'r', to: 'p' },
        { from: 'x', to: 'y' },
        { from: 'y', to: 'x' },
      ],
    );
    expect(r.cycles).toEqual([
      ['p', 'q', 'r', 'p'],
      ['x', 'y', 'x'],
    ]);
    expect(r.order).toEqual([]);
  });

  it('ignores edges that name unknown nodes', () => {
    const r = topologicalOrder(['a'], [{ from: 'ghost', to: 'a' }]);
    expect(r.order).toEqual(['a']);
  });
});
