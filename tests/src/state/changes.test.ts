import { describe, expect, it } from 'vitest';
import { emptyDocument, type GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { applyChange, type Change } from '../../../src/state/changes.ts';

const base = (): GraphDoc => ({
  ...emptyDocument('t'),
  nodes: [
    { id: 'p1', type: 'point', position: [0, 0], params: { x: 1, y: 2 } },
    { id: 'p2', type: 'point', position: [0, 100], params: {} },
    { id: 'l1', type: 'line', position: [200, 0], params: {} },
    { id: 'r1', type: 'reflection', position: [400, 0], params: {} },
    { id: 'r2', type: 'reflection', position: [400, 100], params: {} },
    { id: 'out', type: 'render', position: [600, 0], params: {} },
  ],
  edges: [
    { id: 'e1', from: { node: 'p1', port: 'point' }, to: { node: 'l1', port: 'a' } },
    { id: 'e2', from: { node: 'r1', port: 'element' }, to: { node: 'out', port: 'elements' } },
  ],
});
const apply = (doc: GraphDoc, c: Change) => applyChange(doc, c, registry);

describe('applyChange', () => {
  it('adds a node and refuses a duplicate id', () => {
    const doc = apply(base(), {
      type: 'add-node',
      node: { id: 'n', type: 'number', position: [1, 2], params: {} },
    });
    expect(doc.nodes.map((n) => n.id)).toContain('n');
    expect(() =>
      apply(doc, { type: 'add-node', node: { id: 'n', type: 'number', position: [0, 0], params: {} } }),
    ).toThrow();
  });

  it('removing nodes removes their edges too, and named edges alone', () => {
    const doc = apply(base(), { type: 'remove', nodeIds: ['p1'] });
    expect(doc.nodes.some((n) => n.id === 'p1')).toBe(false);
    expect(doc.edges.map((e) => e.id)).toEqual(['e2']);
    const doc2 = apply(base(), { type: 'remove', nodeIds: [], edgeIds: ['e2'] });
    expect(doc2.edges.map((e) => e.id)).toEqual(['e1']);
    expect(doc2.nodes).toHaveLength(6);
  });

  it('never mutates its input and keeps untouched nodes by identity', () => {
    const doc = base();
    const frozen = JSON.stringify(doc);
    const next = apply(doc, { type: 'set-params', patches: [{ nodeId: 'p1', params: { x: 5 } }] });
    expect(JSON.stringify(doc)).toBe(frozen);
    expect(next.nodes[0].params).toEqual({ x: 5, y: 2 });
    expect(next.nodes[1]).toBe(doc.nodes[1]);
    expect(next.edges).toBe(doc.edges);
  });

  it('set-params merges keys, and undefined removes a key (back to the default)', () => {
    const next = apply(base(), { type: 'set-params', patches: [{ nodeId: 'p1', params: { y: undefined } }] });
    expect(next.nodes[0].params).toEqual({ x: 1 });
  });

  it('moves nodes', () => {
    const next = apply(base(), { type: 'move-nodes', moves: [{ nodeId: 'p2', position: [7, 8] }] });
    expect(next.nodes[1].position).toEqual([7, 8]);
  });

  it('sets and clears a label', () => {
    const a = apply(base(), { type: 'set-label', nodeId: 'p1', label: '  A ' });
    expect(a.nodes[0].label).toBe('A');
    const b = apply(a, { type: 'set-label', nodeId: 'p1', label: '' });
    expect('label' in b.nodes[0]).toBe(false);
  });

  it('a single input keeps one edge: connecting replaces the old one', () => {
    const next = apply(base(), {
      type: 'connect',
      edge: { id: 'e9', from: { node: 'p2', port: 'point' }, to: { node: 'l1', port: 'a' } },
    });
    const into = next.edges.filter((e) => e.to.node === 'l1' && e.to.port === 'a');
    expect(into.map((e) => e.id)).toEqual(['e9']);
  });

  it('an element input takes many edges, but not the same wire twice', () => {
    const wire = { id: 'e9', from: { node: 'r2', port: 'element' }, to: { node: 'out', port: 'elements' } };
    const next = apply(base(), { type: 'connect', edge: wire });
    expect(next.edges.filter((e) => e.to.port === 'elements')).toHaveLength(2);
    const again = apply(next, { type: 'connect', edge: { ...wire, id: 'e10' } });
    expect(again).toBe(next);
  });

  it('batch applies its changes in order as one', () => {
    const next = apply(base(), {
      type: 'batch',
      changes: [
        { type: 'add-node', node: { id: 'r3', type: 'reflection', position: [0, 0], params: {} } },
        {
          type: 'connect',
          edge: { id: 'e3', from: { node: 'r3', port: 'element' }, to: { node: 'out', port: 'elements' } },
        },
      ],
    });
    expect(next.nodes.at(-1)!.id).toBe('r3');
    expect(next.edges.at(-1)!.id).toBe('e3');
  });

  it('load-document replaces the whole document; set-view only the view', () => {
    const other = emptyDocument('other');
    expect(apply(base(), { type: 'load-document', doc: other })).toBe(other);
    const v = apply(base(), { type: 'set-view', view: { center: [1, 1], scale: 2 } });
    expect(v.view).toEqual({ center: [1, 1], scale: 2 });
  });

  it('set-camera-3d stores the 3D camera; null removes it; the same camera is a no-op', () => {
    const camera: NonNullable<GraphDoc['camera3d']> = { position: [1, 2, 3], target: [0, 0, 0], fovDeg: 30 };
    const d = apply(base(), { type: 'set-camera-3d', camera });
    expect(d.camera3d).toEqual(camera);
    expect(
      apply(d, { type: 'set-camera-3d', camera: { ...camera, position: [1, 2, 3], target: [0, 0, 0] } }),
    ).toBe(d);
    const cleared = apply(d, { type: 'set-camera-3d', camera: null });
    expect('camera3d' in cleared).toBe(false);
    expect(apply(cleared, { type: 'set-camera-3d', camera: null })).toBe(cleared);
  });
});
