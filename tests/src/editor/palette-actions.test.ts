import { describe, expect, it } from 'vitest';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { nodesOverlap, sizer } from '../../../src/editor/layout.ts';
import { addNodeChange } from '../../../src/editor/palette-actions.ts';
import { applyChange } from '../../../src/state/changes.ts';

const doc: GraphDoc = {
  ...emptyDocument('t'),
  nodes: [
    { id: 'line1', type: 'line', position: [0, 0], params: {} },
    { id: 'render1', type: 'render', position: [600, 0], params: {} },
  ],
};

describe('adding a node from the palette', () => {
  it('adds it at the cursor', () => {
    const { change, nodeId } = addNodeChange(doc, registry.get('point')!, {
      screen: { x: 0, y: 0 },
      flow: { x: 100, y: 220 },
    });
    const after = applyChange(doc, change, registry);
    const node = after.nodes.find((n) => n.id === nodeId)!;
    expect(node.type).toBe('point');
    expect(node.position).toEqual([100, 200]);
    expect(after.edges).toHaveLength(0);
  });

  it('opened without a pointer (Add node), each new node goes where it covers no other; at the cursor it stays put', () => {
    let d = emptyDocument('t');
    const at = { screen: { x: 0, y: 0 }, flow: { x: 100, y: 220 } };
    for (const type of ['render-3d', 'sphairahedron', 'point']) {
      const { change } = addNodeChange(d, registry.get(type)!, { ...at, centred: true });
      d = applyChange(d, change, registry);
    }
    expect(d.nodes.map((n) => n.position[1])).toEqual([200, 200, 200]);
    expect(nodesOverlap(d, sizer(d, registry))).toBe(false);
    const { change } = addNodeChange(d, registry.get('point')!, at);
    const stacked = applyChange(d, change, registry);
    expect(stacked.nodes.at(-1)!.position).toEqual([100, 200]);
  });

  it('a wire dragged from an output is connected to the new node’s first fitting input', () => {
    const { change, nodeId } = addNodeChange(doc, registry.get('reflection')!, {
      screen: { x: 0, y: 0 },
      flow: { x: 300, y: 0 },
      filter: { from: 'source', type: 'line' },
      wire: { nodeId: 'line1', handle: 'out:line', side: 'source' },
    });
    const after = applyChange(doc, change, registry);
    expect(after.edges).toEqual([
      { id: 'e1', from: { node: 'line1', port: 'line' }, to: { node: nodeId, port: 'line' } },
    ]);
  });

  it('a wire dragged from an input is fed by the new node’s fitting output', () => {
    const { change, nodeId } = addNodeChange(doc, registry.get('reflection')!, {
      screen: { x: 0, y: 0 },
      flow: { x: 500, y: 0 },
      filter: { from: 'target', type: 'element' },
      wire: { nodeId: 'render1', handle: 'in:elements', side: 'target' },
    });
    const after = applyChange(doc, change, registry);
    expect(after.edges[0].from).toEqual({ node: nodeId, port: 'element' });
    expect(after.edges[0].to).toEqual({ node: 'render1', port: 'elements' });
    expect(after.nodes.find((n) => n.id === nodeId)!.position[0]).toBeLessThan(500);
  });
});
