/** Flattening groups, and documents with the graph tools' fields through a save and a load. */
import { describe, expect, it } from 'vitest';
import { LIMITS } from '../../../nodes/core/limits.ts';
import type { GraphDoc, GraphFrame, GraphNode } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { flattenGroups } from '../../../nodes/graph/flatten.ts';
import { groupDef } from '../../../nodes/graph/group-def.ts';
import { groupNodes } from '../../../nodes/graph/grouping.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

/** c → i → out, with c and i grouped as g. */
const grouped = (): GraphDoc =>
  groupNodes(
    doc(
      [node('c', 'circle', { radius: 0.5 }), node('i', 'inversion'), node('out', 'render')],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
    ),
    ['c', 'i'],
    'g',
  );

type Body = NonNullable<GraphNode['group']>;
/** `d` (by default grouped()) with every group's body changed by `edit`. */
const withBody = (edit: (body: Body) => Body, d: GraphDoc = grouped()): GraphDoc => ({
  ...d,
  nodes: d.nodes.map((n) => (n.group ? { ...n, group: edit(n.group) } : n)),
});

describe('flattenGroups', () => {
  it('inlines a group: inner ids kept, outer wires reconnected, the origin of each inner node recorded', () => {
    const { doc: flat, origin } = flattenGroups(grouped());
    expect(flat.nodes.map((n) => n.id)).toEqual(['c', 'i', 'out']);
    expect(flat.edges.map((e) => `${e.from.node}.${e.from.port}>${e.to.node}.${e.to.port}`).sort()).toEqual([
      'c.circle>i.circle',
      'i.element>out.elements',
    ]);
    expect(origin.get('i')).toEqual(['g', 'i']);
    expect(origin.has('out')).toBe(false);
  });

  it('two copies of one group: the second copy’s clashing ids get its group id in front', () => {
    const d = grouped();
    const g = d.nodes.find((n) => n.id === 'g')!;
    const copy: GraphNode = { ...g, id: 'g2' };
    const two = {
      ...d,
      nodes: [...d.nodes, copy],
      edges: [...d.edges, { ...d.edges[0], id: 'e9', from: { node: 'g2', port: 'element' } }],
    };
    const { doc: flat, origin } = flattenGroups(two);
    expect(flat.nodes.map((n) => n.id).sort()).toEqual(['c', 'g2/c', 'g2/i', 'i', 'out']);
    expect(origin.get('g2/c')).toEqual(['g2', 'c']);
    expect(evaluateGraph(two, registry).scene.elements).toHaveLength(2);
  });

  it('two groups with one id: a KF201 error naming both places, never one group silently dropped', () => {
    const d = grouped();
    const g = d.nodes.find((n) => n.id === 'g')!;
    const twin = { ...d, nodes: [...d.nodes, g] };
    const said = evaluateGraph(twin, registry).diagnostics.filter((x) => x.code === 'KF201');
    expect(said).toHaveLength(1);
    expect(said[0]).toMatchObject({ severity: 'error', nodeId: 'g', path: `nodes[${d.nodes.length}].id` });
    expect(said[0].message).toContain(`nodes[${d.nodes.indexOf(g)}] already has it`);
    // A group next to a plain node of its id is the same fault.
    const clash = { ...d, nodes: [...d.nodes, node('g', 'point')] };
    expect(evaluateGraph(clash, registry).diagnostics.filter((x) => x.code === 'KF201')).toHaveLength(1);
  });

  it('two nodes with one id inside one group (at any depth): KF201 at the second, naming the first', () => {
    const inner = withBody((b) => ({ ...b, nodes: [...b.nodes, { ...b.nodes[0] }] }));
    const said = evaluateGraph(inner, registry).diagnostics.filter((x) => x.code === 'KF201');
    expect(said).toHaveLength(1);
    expect(said[0]).toMatchObject({ nodeId: 'c', path: 'nodes[0].group.nodes[2].id' });
    expect(said[0].message).toContain('nodes[0].group.nodes[0]');
    // One level deeper: the group g inside an outer group h.
    const nested = groupNodes(inner, ['g', 'out'], 'h');
    const deep = evaluateGraph(nested, registry).diagnostics.filter((x) => x.code === 'KF201');
    expect(deep).toHaveLength(1);
    expect(deep[0].path).toMatch(/^nodes\[0\]\.group\.nodes\[\d\]\.group\.nodes\[2\]\.id$/);
  });

  it('a muted group mutes every node inside it (its elements leave the picture)', () => {
    const d = grouped();
    const muted = { ...d, nodes: d.nodes.map((n) => (n.id === 'g' ? { ...n, muted: true } : n)) };
    expect(
      flattenGroups(muted)
        .doc.nodes.filter((n) => n.muted)
        .map((n) => n.id),
    ).toEqual(['c', 'i']);
    expect(evaluateGraph(muted, registry).scene.elements).toEqual([]);
  });

  it('the group node’s ports have the inner ports’ types; a wire to a port it no longer has is dropped', () => {
    const g = grouped().nodes.find((n) => n.id === 'g')!;
    const def = groupDef(g, registry)!;
    expect(Object.entries(def.outputs).map(([k, v]) => [k, v.type])).toEqual([['element', 'element']]);
    const broken = { ...grouped(), edges: [{ ...grouped().edges[0], from: { node: 'g', port: 'gone' } }] };
    expect(flattenGroups(broken).doc.edges.map((e) => e.to.node)).toEqual(['i']);
    // Dropped, but said, on the wire's own place in the document.
    const said = evaluateGraph(broken, registry).diagnostics.filter((d) => d.code === 'KF205');
    expect(said).toMatchObject([{ path: 'edges[0].from.port', nodeId: 'g' }]);
    expect(said[0].message).toContain('"gone"');
  });

  it('a wire inside a group to an inner node that is not there is an error at that wire, never dropped silently', () => {
    const broken = withBody((b) => ({
      ...b,
      edges: b.edges.map((e) => ({ ...e, from: { ...e.from, node: 'ghost' } })),
    }));
    const said = evaluateGraph(broken, registry).diagnostics.find((d) => d.code === 'KF204');
    expect(said).toMatchObject({ path: 'nodes[0].group.edges[0].from.node' });
    expect(said?.message).toContain('"ghost"');
  });

  it('a group port naming an inner node that is not there is an error on the group node, at the port', () => {
    const outputGone = withBody((b) => ({
      ...b,
      outputs: b.outputs.map((o) => ({ ...o, from: { ...o.from, node: 'ghost' } })),
    }));
    const out = evaluateGraph(outputGone, registry).diagnostics.find((d) => d.code === 'KF326');
    expect(out).toMatchObject({ nodeId: 'g', path: 'nodes[0].group.outputs[0].from.node' });
    expect(out?.message).toContain('"ghost"');
    // The same for an exposed input (c's centre is exposed once c → i is grouped with p outside).
    const d = groupNodes(
      doc(
        [node('p', 'point'), node('c', 'circle'), node('i', 'inversion'), node('out', 'render')],
        [
          edge('e0', 'p.point', 'c.center'),
          edge('e1', 'c.circle', 'i.circle'),
          edge('e2', 'i.element', 'out.elements'),
        ],
      ),
      ['c', 'i'],
      'g',
    );
    const inputGone = withBody(
      (b) => ({
        ...b,
        inputs: b.inputs.map((p) => ({ ...p, targets: p.targets.map((t) => ({ ...t, node: 'ghost' })) })),
      }),
      d,
    );
    const at = inputGone.nodes.findIndex((n) => n.id === 'g');
    const inp = evaluateGraph(inputGone, registry).diagnostics.find((x) => x.code === 'KF326');
    expect(inp).toMatchObject({ nodeId: 'g', path: `nodes[${at}].group.inputs[0].targets[0].node` });
  });
});

describe('diagnostics of grouped nodes', () => {
  it('name the node’s path in the document', () => {
    const bad = withBody((b) => ({ ...b, nodes: [{ ...b.nodes[0], params: { radius: -1 } }, b.nodes[1]] }));
    const problem = evaluateGraph(bad, registry).diagnostics.find((x) => x.nodeId === 'c');
    expect(problem?.path).toBe('nodes[0].group.nodes[0].params.radius');
  });

  it('name a wire’s path in the document: inside its group, or the outer wire it was copied from', () => {
    // p's point wired into i's circle input: a type mismatch on the wire inside the group.
    const inside = groupNodes(
      doc(
        [node('p', 'point'), node('i', 'inversion'), node('out', 'render')],
        [edge('e1', 'p.point', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
      ),
      ['p', 'i'],
      'g',
    );
    const wrong = evaluateGraph(inside, registry).diagnostics.find((x) => x.code === 'KF206');
    expect(wrong?.path).toBe('nodes[0].group.edges[0]');
    // The same mismatch on a wire from outside into the group's exposed input.
    const outside = groupNodes(
      doc(
        [node('p', 'point'), node('i', 'inversion'), node('out', 'render')],
        [edge('e2', 'i.element', 'out.elements'), edge('e1', 'p.point', 'i.circle')],
      ),
      ['i'],
      'g',
    );
    const flat = flattenGroups(outside);
    expect(flat.edgeOrigin.has('e1')).toBe(false); // a top-level wire keeps its id
    const crossing = evaluateGraph(outside, registry).diagnostics.find((x) => x.code === 'KF206');
    expect(crossing?.path).toBe(`edges[${outside.edges.findIndex((e) => e.id === 'e1')}]`);
  });
});

describe('document round trips', () => {
  it('groups, muted nodes, frames (in groups too) and reroute points survive save and load exactly', () => {
    const d = grouped();
    const inner: GraphFrame = {
      id: 'f',
      title: 'Inside',
      color: '#2f5b4a',
      position: [0, 0],
      size: [200, 100],
    };
    const full: GraphDoc = {
      ...d,
      nodes: d.nodes.map((n) =>
        n.id === 'out'
          ? { ...n, muted: true }
          : n.group
            ? { ...n, group: { ...n.group, frames: [inner] } }
            : n,
      ),
      edges: d.edges.map((e) => ({ ...e, via: [[10, 20] as [number, number]] })),
      frames: [{ id: 'f', title: 'Mirrors', color: '#335577', position: [-20, -40], size: [400, 300] }],
    };
    const r = parseDocumentText(JSON.stringify(full), registry);
    if (!r.ok) throw new Error(JSON.stringify(r.diagnostics));
    expect(r.doc).toEqual(full);
    expect(evaluateGraph(r.doc, registry).scene).toEqual(evaluateGraph(full, registry).scene);
  });

  it('an old document (none of the new fields) loads unchanged, with no new keys', () => {
    const old = doc([node('c', 'circle'), node('i', 'inversion')], [edge('e1', 'c.circle', 'i.circle')]);
    const r = parseDocumentText(JSON.stringify(old), registry);
    if (!r.ok) throw new Error('does not load');
    expect(JSON.stringify(r.doc)).toBe(JSON.stringify(old));
  });

  it('nodes inside groups count towards the node limit', () => {
    const inner = Array.from({ length: LIMITS.maxNodes }, (_, i) => node(`n${i}`, 'point'));
    const big = {
      ...doc([{ ...node('g', 'group'), group: { nodes: inner, edges: [], inputs: [], outputs: [] } }]),
    };
    const r = parseDocumentText(JSON.stringify(big), registry);
    expect(r.ok).toBe(false);
    expect(r.diagnostics[0]).toMatchObject({ code: 'KF105', path: 'nodes' });
  });

  it('a damaged group is refused with the path of the problem', () => {
    const bad = JSON.parse(JSON.stringify(grouped()));
    bad.nodes[0].group.inputs = [{ name: 'x', targets: [] }];
    bad.frames = [{ id: 'f', title: 't', color: 'red', position: [0, 0], size: [1, 1] }];
    const r = parseDocumentText(JSON.stringify(bad), registry);
    expect(r.ok).toBe(false);
    const paths = r.diagnostics.map((d) => d.path);
    expect(paths).toContain('nodes[0].group.inputs[0].targets');
    expect(paths).toContain('frames[0].color');
  });
});
