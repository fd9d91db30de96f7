import { describe, expect, it } from 'vitest';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import {
  clearShift,
  NODE_WIDTH,
  nodesOverlap,
  sizer,
  tidyIfOverlapping,
  tidyPositions,
} from '../../../src/editor/layout.ts';

const doc: GraphDoc = {
  ...emptyDocument('t'),
  nodes: [
    { id: 'out', type: 'render', position: [10, 10], params: {} },
    { id: 'p', type: 'point', position: [0, 0], params: {} },
    { id: 'q', type: 'point', position: [0, 50], params: {} },
    { id: 'l', type: 'line', position: [5, 5], params: {} },
    { id: 'r', type: 'reflection', position: [0, 0], params: {} },
  ],
  edges: [
    { id: 'e1', from: { node: 'p', port: 'point' }, to: { node: 'l', port: 'a' } },
    { id: 'e2', from: { node: 'q', port: 'point' }, to: { node: 'l', port: 'b' } },
    { id: 'e3', from: { node: 'l', port: 'line' }, to: { node: 'r', port: 'line' } },
    { id: 'e4', from: { node: 'r', port: 'element' }, to: { node: 'out', port: 'elements' } },
  ],
};

describe('tidy layout', () => {
  it('puts nodes in columns by depth, stacked without overlap', () => {
    const size = sizer(doc, registry);
    expect(nodesOverlap(doc, size)).toBe(true);
    const at = new Map(tidyPositions(doc, size).map((m) => [m.nodeId, m.position]));
    expect(at.get('p')![0]).toBe(at.get('q')![0]);
    expect(at.get('l')![0]).toBeGreaterThan(at.get('p')![0]);
    expect(at.get('r')![0]).toBeGreaterThan(at.get('l')![0]);
    expect(at.get('out')![0]).toBeGreaterThan(at.get('r')![0]);
    expect(at.get('q')![1]).toBeGreaterThan(at.get('p')![1]); // keeps the vertical order
    const tidy = tidyIfOverlapping(doc, registry);
    expect(nodesOverlap(tidy, sizer(tidy, registry))).toBe(false);
    expect(tidyIfOverlapping(tidy, registry)).toBe(tidy); // already tidy: untouched
  });

  it('terminates on a cycle', () => {
    const cyclic: GraphDoc = {
      ...doc,
      edges: [...doc.edges, { id: 'e5', from: { node: 'l', port: 'line' }, to: { node: 'l', port: 'a' } }],
    };
    expect(tidyPositions(cyclic, sizer(cyclic, registry))).toHaveLength(5);
  });
});

describe('a clear spot for new nodes', () => {
  const size = sizer(doc, registry);
  it('leaves nodes that cover nothing where they are', () => {
    expect(clearShift(doc, [{ id: 'n', type: 'point', position: [2000, 0], params: {} }], size)).toBe(0);
  });
  it('moves a pasted group right, as one, until none of it covers a node', () => {
    const pasted = [
      { id: 'a', type: 'point', position: [0, 0] as [number, number], params: {} },
      { id: 'b', type: 'line', position: [0, 300] as [number, number], params: {} },
    ];
    const dx = clearShift(doc, pasted, size);
    expect(dx).toBeGreaterThanOrEqual(NODE_WIDTH);
    const moved = pasted.map((n) => ({
      ...n,
      position: [n.position[0] + dx, n.position[1]] as [number, number],
    }));
    // Moved, the group covers nothing: it would not move again.
    expect(clearShift(doc, moved, size)).toBe(0);
  });
});
