import { describe, expect, it } from 'vitest';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { copyNodes, parseClipboard, preparePaste, serializeClipboard } from '../../../src/state/clipboard.ts';

const doc: GraphDoc = {
  ...emptyDocument('t'),
  nodes: [
    { id: 'point1', type: 'point', position: [0, 0], params: { x: 1 } },
    { id: 'point2', type: 'point', position: [0, 100], params: {} },
    { id: 'line1', type: 'line', position: [200, 50], params: {}, label: 'AB' },
  ],
  edges: [
    { id: 'e1', from: { node: 'point1', port: 'point' }, to: { node: 'line1', port: 'a' } },
    { id: 'e2', from: { node: 'point2', port: 'point' }, to: { node: 'line1', port: 'b' } },
  ],
};

describe('clipboard', () => {
  it('copies the chosen nodes with only the edges between them', () => {
    const data = copyNodes(doc, ['point1', 'line1'])!;
    expect(data.format).toBe('kleinflow-clipboard');
    expect(data.nodes.map((n) => n.id)).toEqual(['point1', 'line1']);
    expect(data.edges.map((e) => e.id)).toEqual(['e1']);
    expect(copyNodes(doc, [])).toBeNull();
  });

  it('round-trips through JSON text and rejects anything else', () => {
    const data = copyNodes(doc, ['point1'])!;
    expect(parseClipboard(serializeClipboard(data))).toEqual(data);
    expect(parseClipboard('hello')).toBeNull();
    expect(parseClipboard('{"format":"kleinflow","nodes":[],"edges":[]}')).toBeNull();
    expect(parseClipboard('{"format":"kleinflow-clipboard","nodes":[{"id":1}],"edges":[]}')).toBeNull();
  });

  it('pastes with fresh ids and titles, edges rewired between the copies, offset positions, params kept', () => {
    const data = copyNodes(doc, ['point1', 'point2', 'line1'])!;
    const { nodes, edges } = preparePaste(doc, data);
    const oldIds = new Set(doc.nodes.map((n) => n.id));
    expect(nodes.every((n) => !oldIds.has(n.id))).toBe(true);
    expect(new Set(nodes.map((n) => n.id)).size).toBe(3);
    expect(nodes[0].position).toEqual([40, 40]);
    expect(nodes[0].params).toEqual({ x: 1 });
    // Titles taken in the document get the next free number, so copies are told apart.
    expect(nodes.map((n) => n.label)).toEqual(['Point 2', 'Point 3', 'AB 2']);
    // Into a document without those titles, the first keeps its type's name, 'AB' its label.
    const elsewhere = preparePaste({ ...doc, nodes: [], edges: [] }, data).nodes;
    expect(elsewhere.map((n) => n.label)).toEqual([undefined, 'Point 2', 'AB']);
    expect(edges).toHaveLength(2);
    const ids = new Set(nodes.map((n) => n.id));
    for (const e of edges) expect(ids.has(e.from.node) && ids.has(e.to.node)).toBe(true);
    // The paste is a valid change: ids never clash with the document's.
    const after = applyChange(doc, { type: 'paste', nodes, edges }, registry);
    expect(after.nodes).toHaveLength(6);
    expect(new Set(after.edges.map((e) => e.id)).size).toBe(4);
  });

  it('pastes at a given point (top-left corner of the group)', () => {
    const data = copyNodes(doc, ['point2', 'line1'])!;
    const { nodes } = preparePaste(doc, data, [500, 500]);
    expect(nodes.map((n) => n.position)).toEqual([
      [500, 550],
      [700, 500],
    ]);
  });
});
