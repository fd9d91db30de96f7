import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { closesCycle, topologicalOrder } from '../../../nodes/graph/topo.ts';
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

/** Reference: whether `to` is reachable from `from` (a plain graph search, for the property). */
function reaches(edges: readonly { from: string; to: string }[], from: string, to: string): boolean {
  const seen = new Set<string>();
  const stack = [from];
  while (stack.length > 0) {
    const id = stack.pop()!;
    if (id === to) return true;
    if (seen.has(id)) continue;
    seen.add(id);
    for (const e of edges) if (e.from === id) stack.push(e.to);
  }
  return false;
}

describe('closesCycle (the editor refuses such a wire)', () => {
  const chain = [
    { from: 'a', to: 'b' },
    { from: 'b', to: 'c' },
  ];
  it('a wire back up a chain, or into itself, closes a cycle; one down or across does not', () => {
    const ids = ['a', 'b', 'c', 'd'];
    expect(closesCycle(ids, chain, { from: 'c', to: 'a' })).toBe(true);
    expect(closesCycle(ids, chain, { from: 'b', to: 'a' })).toBe(true);
    expect(closesCycle(ids, chain, { from: 'd', to: 'd' })).toBe(true);
    expect(closesCycle(ids, chain, { from: 'a', to: 'c' })).toBe(false);
    expect(closesCycle(ids, chain, { from: 'd', to: 'a' })).toBe(false);
    expect(closesCycle(ids, chain, { from: 'c', to: 'd' })).toBe(false);
  });

  it('a cycle elsewhere in the graph does not block unrelated wires, nor hide a new cycle', () => {
    const ids = ['a', 'b', 'c', 'x', 'y'];
    const edges = [...chain, { from: 'x', to: 'y' }, { from: 'y', to: 'x' }];
    expect(closesCycle(ids, edges, { from: 'a', to: 'c' })).toBe(false);
    expect(closesCycle(ids, edges, { from: 'c', to: 'a' })).toBe(true);
    expect(closesCycle(ids, edges, { from: 'c', to: 'x' })).toBe(false); // into the old cycle, not a new one
  });

  it('from a node downstream of an existing cycle, the wire is allowed (analysis reports cycles)', () => {
    const ids = ['x', 'y', 'a', 'b'];
    const edges = [
      { from: 'x', to: 'y' },
      { from: 'y', to: 'x' },
      { from: 'y', to: 'a' },
      { from: 'a', to: 'b' },
    ];
    expect(closesCycle(ids, edges, { from: 'b', to: 'a' })).toBe(false);
    // …and evaluation's ordering then reports the new cycle as well as the old one.
    expect(topologicalOrder(ids, [...edges, { from: 'b', to: 'a' }]).cycles).toHaveLength(2);
  });

  it('on random acyclic graphs, agrees with a graph search: u → v closes a cycle iff v reaches u', () => {
    const graph = fc
      .integer({ min: 2, max: 14 })
      .chain((n) =>
        fc.tuple(
          fc.constant(Array.from({ length: n }, (_, i) => `n${i}`)),
          fc.array(fc.tuple(fc.nat(n - 1), fc.nat(n - 1)), { maxLength: 30 }),
          fc.nat(n - 1),
          fc.nat(n - 1),
        ),
      );
    fc.assert(
      fc.property(graph, ([ids, pairs, u, v]) => {
        const edges = pairs.filter(([i, j]) => i < j).map(([i, j]) => ({ from: ids[i], to: ids[j] }));
        const edge = { from: ids[u], to: ids[v] };
        expect(closesCycle(ids, edges, edge)).toBe(reaches(edges, edge.to, edge.from));
      }),
      { seed: 7, numRuns: 300 },
    );
  });
});
