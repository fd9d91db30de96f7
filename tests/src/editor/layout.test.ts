import { readFileSync } from 'node:fs';
import { join } from 'node:path';
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
    const at = new Map(tidyPositions(doc, size, registry).map((m) => [m.nodeId, m.position]));
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
    expect(tidyPositions(cyclic, sizer(cyclic, registry), registry)).toHaveLength(5);
  });
});

describe('tidy layout flows left to right', () => {
  const k333 = JSON.parse(
    readFileSync(
      join(import.meta.dirname, '..', '..', '..', 'examples', 'kaleidoscope-333.kleinflow.json'),
      'utf8',
    ),
  ) as GraphDoc;
  const place = (d: GraphDoc) =>
    new Map(tidyPositions(d, sizer(d, registry), registry).map((m) => [m.nodeId, m.position]));

  it('puts Render alone on the right, each wire one column long, crossing as little as can be', () => {
    const at = place(k333);
    const column = (id: string) => at.get(id)![0];
    const right = Math.max(...[...at.values()].map((p) => p[0]));
    expect(column('out')).toBe(right);
    expect([...at.keys()].filter((id) => column(id) === right)).toEqual(['out']);
    for (const e of k333.edges) expect(column(e.to.node)).toBeGreaterThan(column(e.from.node));
    // The tile feeds only Render: it sits in the column before it, not far left with a long wire.
    expect(column('t')).toBe(column('mAB'));
    let crossings = 0;
    for (const [i, a] of k333.edges.entries())
      for (const b of k333.edges.slice(i + 1)) {
        if (column(a.from.node) !== column(b.from.node) || column(a.to.node) !== column(b.to.node)) continue;
        const dy0 = at.get(a.from.node)![1] - at.get(b.from.node)![1];
        const dy1 = at.get(a.to.node)![1] - at.get(b.to.node)![1];
        if (dy0 * dy1 < 0) crossings++;
      }
    // Points and lines make a six-cycle (A–AB–B–BC–C–CA–A), which two columns cannot draw with
    // fewer than two crossings; the mirrors, the tile and Render add none.
    expect(crossings).toBe(2);
  });

  it('puts an unwired Render on the right, not at the bottom left', () => {
    const bare: GraphDoc = { ...doc, edges: doc.edges.filter((e) => e.to.node !== 'out') };
    const at = place(bare);
    expect(at.get('out')![0]).toBe(Math.max(...[...at.values()].map((p) => p[0])));
    expect(at.get('out')![0]).toBeGreaterThan(at.get('p')![0]);
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
