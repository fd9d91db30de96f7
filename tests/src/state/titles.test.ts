import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { nodeName, nodeNames, ordinal } from '../../../nodes/graph/node-names.ts';
import { registry } from '../../../nodes/types/index.ts';
import { newNode } from '../../../src/editor/new-node.ts';
import { titleAllocator } from '../../../src/state/titles.ts';

const empty: GraphDoc = { format: 'kleinflow', version: 1, nodes: [], edges: [] } as unknown as GraphDoc;
const def = registry.get('reflection')!;

describe('node titles', () => {
  it('new nodes of one type get distinct titles; the first keeps the type name', () => {
    let doc = empty;
    for (let i = 0; i < 3; i++) doc = { ...doc, nodes: [...doc.nodes, newNode(doc, def, [0, 0])] };
    expect(doc.nodes.map((n) => n.label)).toEqual([undefined, 'Line reflection 2', 'Line reflection 3']);
    // A freed number is used again; other types start over.
    const gap = { ...doc, nodes: doc.nodes.filter((n) => n.label !== 'Line reflection 2') };
    expect(newNode(gap, def, [0, 0]).label).toBe('Line reflection 2');
    expect(newNode(doc, registry.get('point')!, [0, 0]).label).toBeUndefined();
  });

  it('a taken title of any kind gets the next number of its stem', () => {
    const next = titleAllocator([{ type: 'point', label: 'A' }, { type: 'point' }], registry);
    expect(next({ type: 'point', label: 'A' })).toBe('A 2');
    expect(next({ type: 'point', label: 'A' })).toBe('A 3');
    expect(next({ type: 'point' })).toBe('Point 2');
    expect(next({ type: 'point', label: 'B' })).toBe('B');
  });

  it('messages name nodes by title; titles shared (old documents) get their place', () => {
    const nodes = [
      { id: 'reflection1', type: 'reflection' },
      { id: 'reflection2', type: 'reflection' },
      { id: 'p', type: 'point', label: 'A' },
      { id: 'reflection3', type: 'reflection', label: 'Line reflection 3' },
    ];
    const names = nodeNames(nodes, (n) => registry.get(n.type)?.label);
    expect([...names.values()]).toEqual([
      '“Line reflection” (1st)',
      '“Line reflection” (2nd)',
      '“A”',
      '“Line reflection 3”',
    ]);
    const table = new Map(
      nodes.map((node, index) => [node.id, { node, index, def: registry.get(node.type) }]),
    );
    expect(nodeName(table, 'reflection2')).toBe('“Line reflection” (2nd)');
    expect([1, 2, 3, 4, 11, 12, 13, 21, 22, 101].map(ordinal).join(' ')).toBe(
      '1st 2nd 3rd 4th 11th 12th 13th 21st 22nd 101st',
    );
  });
});
