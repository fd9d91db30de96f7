import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import { analyzeGraph } from '../../../nodes/graph/analyze.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node, shuffled } from '../support/doc.ts';

const codes = (ds: readonly Diagnostic[]) => ds.map((d) => d.code);
const only = (ds: readonly Diagnostic[], code: string) => ds.filter((d) => d.code === code);

/** p1 → c1.center, c1 → inv1 → out (a small valid chain used by most cases). */
const chain = () => ({
  nodes: [
    node('p1', 'point', { x: 1, y: 0 }),
    node('c1', 'circle', { radius: 0.5 }),
    node('inv1', 'inversion'),
    node('out', 'render'),
  ],
  edges: [
    edge('e1', 'p1.point', 'c1.center'),
    edge('e2', 'c1.circle', 'inv1.circle'),
    edge('e3', 'inv1.element', 'out.elements'),
  ],
});

describe('analyzeGraph', () => {
  it('accepts a valid chain without diagnostics and orders it', () => {
    const { nodes, edges } = chain();
    const a = analyzeGraph(doc(nodes, edges), registry);
    expect(a.diagnostics).toEqual([]);
    expect(a.order).toEqual(['p1', 'c1', 'inv1', 'out']);
    expect(
      a.incoming
        .get('c1')
        ?.get('center')
        ?.map((e) => e.id),
    ).toEqual(['e1']);
  });

  it('orders the same for any shuffle of nodes and edges', () => {
    const { nodes, edges } = chain();
    nodes.push(node('a0', 'point'), node('zz', 'number'), node('c0', 'circle'));
    edges.push(edge('e4', 'a0.point', 'c0.center'));
    const base = analyzeGraph(doc(nodes, edges), registry).order;
    for (let seed = 1; seed <= 10; seed++) {
      const a = analyzeGraph(doc(shuffled(nodes, seed), shuffled(edges, seed * 7)), registry);
      expect(a.order).toEqual(base);
    }
    expect(base).toEqual(['a0', 'c0', 'p1', 'c1', 'inv1', 'out', 'zz']);
  });

  it('KF201: a duplicate node id names the second occurrence; the first wins', () => {
    const a = analyzeGraph(doc([node('x', 'point', { x: 1 }), node('x', 'circle')]), registry);
    const [d] = only(a.diagnostics, 'KF201');
    expect(d).toMatchObject({ path: 'nodes[1].id', nodeId: 'x', severity: 'error' });
    expect(d.message).toContain('"x"');
    expect(a.nodes.get('x')?.node.type).toBe('point');
  });

  it('KF202: a duplicate edge id is reported with its path and not used', () => {
    const { nodes, edges } = chain();
    edges.push({ ...edge('e1', 'p1.point', 'c1.center') });
    const a = analyzeGraph(doc(nodes, edges), registry);
    expect(only(a.diagnostics, 'KF202')).toEqual([expect.objectContaining({ path: 'edges[3].id' })]);
    expect(only(a.diagnostics, 'KF207')).toEqual([]);
  });

  it('KF203: an unknown node type is kept as a placeholder, its edges unused but not dropped', () => {
    const d = doc(
      [node('p', 'point'), node('w', 'warp-drive', { power: 11 }), node('out', 'render')],
      [edge('e1', 'p.point', 'w.in'), edge('e2', 'w.element', 'out.elements')],
    );
    const a = analyzeGraph(d, registry);
    expect(codes(a.diagnostics)).toEqual(['KF203']);
    expect(a.diagnostics[0]).toMatchObject({ path: 'nodes[1].type', nodeId: 'w' });
    expect(a.diagnostics[0].message).toContain('warp-drive');
    expect(a.nodes.get('w')).toMatchObject({ def: undefined, node: { params: { power: 11 } } });
    expect(a.order).toContain('w');
    const ev = evaluateGraph(d, registry);
    expect(ev.nodes.get('w')).toEqual({ diagnostics: [] });
    expect(ev.scene.elements).toEqual([]);
    expect(d.nodes).toHaveLength(3); // never silently dropped
    // the render says which source is missing
    expect(ev.diagnostics.find((x) => x.nodeId === 'out')).toMatchObject({
      code: 'KF302',
      severity: 'warning',
    });
  });

  it('a node fed by a placeholder reports it instead of using its inline default', () => {
    const d = doc(
      [node('w', 'warp-drive'), node('i', 'inversion'), node('out', 'render')],
      [edge('e1', 'w.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
    );
    const ev = evaluateGraph(d, registry);
    const [d302] = ev.diagnostics.filter((x) => x.nodeId === 'i');
    expect(d302).toMatchObject({ code: 'KF302', severity: 'error', port: 'circle' });
    expect(d302.message).toContain('“warp-drive” failed'); // an unknown type is named by its type
    expect(ev.scene.elements).toEqual([]); // not a unit-circle inversion from the default
    expect(ev.analysis.order.indexOf('w')).toBeLessThan(ev.analysis.order.indexOf('i'));
  });

  it('KF204: dangling edges name the missing end', () => {
    const a = analyzeGraph(
      doc(
        [node('p', 'point'), node('c', 'circle')],
        [edge('e1', 'ghost.point', 'c.center'), edge('e2', 'p.point', 'nobody.center')],
      ),
      registry,
    );
    const ds = only(a.diagnostics, 'KF204');
    expect(ds.map((d) => d.path)).toEqual(['edges[0].from.node', 'edges[1].to.node']);
    expect(ds[0].message).toContain('"ghost"');
    expect(ds[1].message).toContain('"nobody"');
    expect(a.incoming.size).toBe(0);
  });

  it('KF205: unknown ports on either end', () => {
    const a = analyzeGraph(
      doc(
        [node('p', 'point'), node('c', 'circle')],
        [edge('e1', 'p.pointy', 'c.center'), edge('e2', 'p.point', 'c.centre')],
      ),
      registry,
    );
    const ds = only(a.diagnostics, 'KF205');
    expect(ds).toEqual([
      expect.objectContaining({ path: 'edges[0].from.port', nodeId: 'p' }),
      expect.objectContaining({ path: 'edges[1].to.port', nodeId: 'c' }),
    ]);
    expect(ds[0].message).toContain('"pointy"');
    expect(ds[1].message).toContain('"centre"');
  });

  it('KF205: an edge from a placeholder into a port that does not exist', () => {
    const a = analyzeGraph(
      doc([node('w', 'warp-drive'), node('c', 'circle')], [edge('e1', 'w.out', 'c.rim')]),
      registry,
    );
    expect(a.diagnostics.map((d) => [d.code, d.path])).toEqual([
      ['KF203', 'nodes[0].type'],
      ['KF205', 'edges[0].to.port'],
    ]);
  });

  it('KF206: a point cannot feed a circle input', () => {
    const a = analyzeGraph(
      doc([node('p', 'point'), node('i', 'inversion')], [edge('e1', 'p.point', 'i.circle')]),
      registry,
    );
    expect(only(a.diagnostics, 'KF206')).toEqual([
      expect.objectContaining({
        path: 'edges[0]',
        nodeId: 'i',
        port: 'circle',
        message: 'cannot connect a point output to a circle input',
      }),
    ]);
    expect(a.incoming.size).toBe(0);
  });

  it('KF207: several edges into a single input keep the first and report the second', () => {
    const a = analyzeGraph(
      doc(
        [node('p', 'point'), node('q', 'point'), node('c', 'circle')],
        [edge('e1', 'p.point', 'c.center'), edge('e2', 'q.point', 'c.center')],
      ),
      registry,
    );
    expect(only(a.diagnostics, 'KF207')).toEqual([
      expect.objectContaining({ path: 'edges[1]', nodeId: 'c', port: 'center' }),
    ]);
    expect(
      a.incoming
        .get('c')
        ?.get('center')
        ?.map((e) => e.id),
    ).toEqual(['e1']);
  });

  it('element inputs take many edges without complaint', () => {
    const a = analyzeGraph(
      doc(
        [node('i1', 'inversion'), node('i2', 'inversion'), node('out', 'render')],
        [edge('e1', 'i1.element', 'out.elements'), edge('e2', 'i2.element', 'out.elements')],
      ),
      registry,
    );
    expect(a.diagnostics).toEqual([]);
    expect(a.incoming.get('out')?.get('elements')).toHaveLength(2);
  });

  it('KF209: a node wired to itself', () => {
    const a = analyzeGraph(doc([node('n', 'number')], [edge('e1', 'n.value', 'n.value')]), registry);
    expect(only(a.diagnostics, 'KF209')).toEqual([
      expect.objectContaining({ path: 'edges[0]', nodeId: 'n' }),
    ]);
    expect(a.order).toEqual(['n']);
  });

  it('KF208: a cycle is reported on each node on it, with the path', () => {
    const a = analyzeGraph(
      doc(
        [
          node('n1', 'number'),
          node('n2', 'number'),
          node('n3', 'number'),
          node('after', 'point'),
          node('free', 'point'),
        ],
        [
          edge('e1', 'n1.value', 'n2.value'),
          edge('e2', 'n2.value', 'n3.value'),
          edge('e3', 'n3.value', 'n1.value'),
          edge('e4', 'n3.value', 'after.x'),
        ],
      ),
      registry,
    );
    const ds = only(a.diagnostics, 'KF208');
    expect(ds.map((d) => d.nodeId)).toEqual(['n1', 'n2', 'n3']);
    expect(ds.map((d) => d.path)).toEqual(['nodes[0]', 'nodes[1]', 'nodes[2]']);
    for (const d of ds) expect(d.message).toBe('cycle through nodes n1 → n2 → n3 → n1');
    expect(a.order).toEqual(['free']);
    expect([...a.blocked].sort()).toEqual(['after', 'n1', 'n2', 'n3']);
  });

  it('a cycle does not stop evaluation of the rest', () => {
    const { nodes, edges } = chain();
    nodes.push(node('n1', 'number'), node('n2', 'number'));
    edges.push(edge('e8', 'n1.value', 'n2.value'), edge('e9', 'n2.value', 'n1.value'));
    const ev = evaluateGraph(doc(nodes, edges), registry);
    expect(codes(ev.diagnostics)).toEqual(['KF208', 'KF208']);
    expect(ev.scene.elements).toHaveLength(1);
    expect(ev.nodes.get('n1')).toEqual({ diagnostics: [] });
  });
});
