import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

describe('intersection nodes', () => {
  it('defaults give their points', () => {
    expect(checkDefaults('intersect-lines').outputs!.point).toEqual([0, 0]);
    const lc = checkDefaults('intersect-line-circle');
    expect(lc.readout).toBe('two points');
    const cc = checkDefaults('intersect-circles').outputs!;
    expect((cc.p1 as number[])[1]).toBeCloseTo(-Math.sqrt(0.75), 12);
    expect((cc.p2 as number[])[1]).toBeCloseTo(Math.sqrt(0.75), 12);
  });

  it('no intersection is a warning and leaves the outputs empty; dependants say why', () => {
    const parallel = evalNode('intersect-lines', {
      l1: { a: [0, 0], b: [1, 0] },
      l2: { a: [0, 1], b: [1, 1] },
    });
    expect(codes(parallel, 'warning')).toEqual(['KF307']);
    expect(codes(parallel)).toEqual([]);
    expect(parallel.outputs).toEqual({});
    const apart = evalNode('intersect-circles', { c1: { c: [0, 0], r: 1 }, c2: { c: [5, 0], r: 1 } });
    expect(apart.diagnostics[0].message).toMatch(/lie apart/);
    const miss = evalNode('intersect-line-circle', { line: { a: [-1, 3], b: [1, 3] } });
    expect(codes(miss, 'warning')).toEqual(['KF307']);
    const graph = evaluateGraph(
      doc(
        [
          node('x', 'intersect-circles', { c1: { c: [0, 0], r: 1 }, c2: { c: [5, 0], r: 1 } }),
          node('m', 'midpoint'),
        ],
        [edge('e', 'x.p1', 'm.a')],
      ),
      registry,
    );
    expect(codes(graph.nodes.get('m')!)).toEqual(['KF308']); // "x has no p1 output in its current set-up"
  });

  it('tangent figures give the touching point on both outputs', () => {
    const t = evalNode('intersect-circles', { c1: { c: [0, 0], r: 1 }, c2: { c: [2, 0], r: 1 } });
    expect(t.outputs!.p1).toEqual(t.outputs!.p2);
    expect(t.readout).toBe('tangent: one point');
    const l = evalNode('intersect-line-circle', { line: { a: [-1, 1], b: [1, 1] } });
    expect(l.outputs!.p1).toEqual(l.outputs!.p2);
  });

  it('degenerate inputs are errors', () => {
    expect(codes(evalNode('intersect-lines', { l1: { a: [1, 1], b: [1, 1] } }))).toEqual(['KF303']);
    expect(codes(evalNode('intersect-circles', { c1: { c: [0, 0], r: 0 } }))).toEqual(['KF303']);
  });
});
