import { describe, expect, it } from 'vitest';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { checkConnection, inHandle, outHandle } from '../../../src/editor/connection.ts';

const doc: GraphDoc = {
  ...emptyDocument('t'),
  nodes: [
    { id: 'p', type: 'point', position: [0, 0], params: {} },
    { id: 'n', type: 'number', position: [0, 0], params: {} },
    { id: 'l', type: 'line', position: [0, 0], params: {} },
    { id: 'r', type: 'reflection', position: [0, 0], params: {} },
    { id: 'c', type: 'circle', position: [0, 0], params: {} },
    { id: 'out', type: 'render', position: [0, 0], params: {} },
  ],
  edges: [{ id: 'e', from: { node: 'n', port: 'value' }, to: { node: 'c', port: 'radius' } }],
};
const wire = (source: string, sp: string, target: string, tp: string) => ({
  source,
  sourceHandle: outHandle(sp),
  target,
  targetHandle: inHandle(tp),
});

describe('connection rules', () => {
  it('allows matching port types', () => {
    expect(checkConnection(doc, registry, wire('p', 'point', 'l', 'a')).ok).toBe(true);
    expect(checkConnection(doc, registry, wire('r', 'element', 'out', 'elements')).ok).toBe(true);
  });

  it('refuses mismatched types, with the reason', () => {
    const v = checkConnection(doc, registry, wire('p', 'point', 'r', 'line'));
    expect(v).toEqual({ ok: false, reason: 'a point output cannot feed a line input' });
    expect(checkConnection(doc, registry, wire('n', 'value', 'l', 'a')).ok).toBe(false);
  });

  it('refuses self loops, unknown ports and cycles', () => {
    expect(checkConnection(doc, registry, wire('c', 'circle', 'c', 'radius')).ok).toBe(false);
    expect(checkConnection(doc, registry, wire('p', 'nope', 'l', 'a')).ok).toBe(false);
    const cyclic: GraphDoc = {
      ...doc,
      nodes: [...doc.nodes, { id: 'n2', type: 'number', position: [0, 0], params: {} }],
      edges: [{ id: 'e', from: { node: 'n', port: 'value' }, to: { node: 'n2', port: 'value' } }],
    };
    expect(checkConnection(cyclic, registry, wire('n2', 'value', 'n', 'value'))).toEqual({
      ok: false,
      reason: 'this wire would make a cycle',
    });
  });

  it('a cycle the document already has elsewhere blocks no unrelated wire, and a longer cycle is refused', () => {
    const looped: GraphDoc = {
      ...doc,
      nodes: [...doc.nodes, { id: 'n2', type: 'number', position: [0, 0], params: {} }],
      edges: [
        ...doc.edges,
        { id: 'x1', from: { node: 'n', port: 'value' }, to: { node: 'n2', port: 'value' } },
        { id: 'x2', from: { node: 'n2', port: 'value' }, to: { node: 'n', port: 'value' } },
      ],
    };
    expect(checkConnection(looped, registry, wire('p', 'point', 'l', 'a')).ok).toBe(true);
    // p → mid → l → rp: a wire from rp back into mid closes mid → l → rp → mid
    const chained: GraphDoc = {
      ...doc,
      nodes: [
        ...doc.nodes,
        { id: 'mid', type: 'midpoint', position: [0, 0], params: {} },
        { id: 'rp', type: 'reflect-point', position: [0, 0], params: {} },
      ],
      edges: [
        { id: 'e1', from: { node: 'p', port: 'point' }, to: { node: 'mid', port: 'a' } },
        { id: 'e2', from: { node: 'mid', port: 'point' }, to: { node: 'l', port: 'a' } },
        { id: 'e3', from: { node: 'l', port: 'line' }, to: { node: 'rp', port: 'line' } },
      ],
    };
    expect(checkConnection(chained, registry, wire('rp', 'point', 'mid', 'b'))).toEqual({
      ok: false,
      reason: 'this wire would make a cycle',
    });
    expect(checkConnection(chained, registry, wire('rp', 'point', 'l', 'b')).ok).toBe(false);
    expect(checkConnection(chained, registry, wire('mid', 'point', 'rp', 'point')).ok).toBe(true);
  });
});
