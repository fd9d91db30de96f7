import { describe, expect, it } from 'vitest';
import { defineNode } from '../../../nodes/core/define-node.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { dragPatches, firstHandle, originalParams } from '../../../nodes/graph/drag-patches.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { NODE_TYPES, registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../../src/viewport/overlay/fixtures.ts';

/** A point that passes its input through and offers it as a handle (like a "snap to" node). */
const relayNode = defineNode({
  type: 'relay',
  version: 1,
  label: 'Relay',
  category: 'Geometry',
  color: '#ffffff',
  doc: 'test only: passes a point through',
  inputs: { p: { type: 'point', default: [0, 0] } },
  outputs: { point: { type: 'point' } },
  params: {},
  evaluate: ({ inputs }) => ({ outputs: { point: inputs.p } }),
  handles: (ctx) => [{ handle: 'p', at: ctx.inputs.p as Vec2 }],
  drag: (_h, to) => ({ p: [...to] }),
});

describe('dragPatches', () => {
  it('patches an unconnected circle directly: centre and rim', () => {
    const ev = evaluateGraph(doc([node('c', 'circle', { center: [0, 0], radius: 1 })]), registry);
    expect(dragPatches(ev, { nodeId: 'c', handle: 'center' }, [0.5, -0.25])).toEqual([
      { nodeId: 'c', params: { center: [0.5, -0.25] } },
    ]);
    expect(dragPatches(ev, { nodeId: 'c', handle: 'rim' }, [0, 2])).toEqual([
      { nodeId: 'c', params: { radius: 2 } },
    ]);
  });

  it('forwards a wired centre to the upstream point and keeps the rim on the circle', () => {
    const ev = evaluateGraph(
      doc(
        [node('p', 'point', { x: 1, y: 1 }), node('c', 'circle', { radius: 0.5 })],
        [edge('p', 'point', 'c', 'center')],
      ),
      registry,
    );
    expect(dragPatches(ev, { nodeId: 'c', handle: 'center' }, [2, 3])).toEqual([
      { nodeId: 'p', params: { x: 2, y: 3 } },
    ]);
    // The rim's radius is measured from the wired centre (1, 1).
    expect(dragPatches(ev, { nodeId: 'c', handle: 'rim' }, [1, 2.5])).toEqual([
      { nodeId: 'c', params: { radius: 1.5 } },
    ]);
  });

  it('drops keys wired from something that cannot be dragged (a number node)', () => {
    const ev = evaluateGraph(
      doc(
        [node('n', 'number', { value: 2 }), node('c', 'circle', { center: [0, 0] })],
        [edge('n', 'value', 'c', 'radius')],
      ),
      registry,
    );
    expect(dragPatches(ev, { nodeId: 'c', handle: 'rim' }, [3, 0])).toEqual([]);
    expect(dragPatches(ev, { nodeId: 'c', handle: 'center' }, [1, 0])).toEqual([
      { nodeId: 'c', params: { center: [1, 0] } },
    ]);
  });

  it('moves one end of a line wired from a point and the free end directly', () => {
    const ev = evaluateGraph(
      doc(
        [node('p', 'point', { x: -1, y: 0 }), node('l', 'line', { b: [1, 0] })],
        [edge('p', 'point', 'l', 'a')],
      ),
      registry,
    );
    expect(dragPatches(ev, { nodeId: 'l', handle: 'a' }, [-2, 1])).toEqual([
      { nodeId: 'p', params: { x: -2, y: 1 } },
    ]);
    expect(dragPatches(ev, { nodeId: 'l', handle: 'b' }, [2, 1])).toEqual([
      { nodeId: 'l', params: { b: [2, 1] } },
    ]);
  });

  it('follows a chain of wired points up to the depth limit', () => {
    const reg = createRegistry([...NODE_TYPES, relayNode]);
    const chain = doc(
      [node('p', 'point', { x: 0, y: 0 }), node('r1', 'relay'), node('r2', 'relay'), node('c', 'circle')],
      [edge('p', 'point', 'r1', 'p'), edge('r1', 'point', 'r2', 'p'), edge('r2', 'point', 'c', 'center')],
    );
    const ev = evaluateGraph(chain, reg);
    expect(dragPatches(ev, { nodeId: 'c', handle: 'center' }, [4, 5])).toEqual([
      { nodeId: 'p', params: { x: 4, y: 5 } },
    ]);
    expect(dragPatches(ev, { nodeId: 'c', handle: 'center' }, [4, 5], 2)).toEqual([]);
  });

  it('moves every point of a circle through three points that is wired', () => {
    const ev = evaluateGraph(
      doc(
        [node('p', 'point', { x: 0, y: 1 }), node('k', 'circle-3pt', { a: [-1, 0], c: [1, 0] })],
        [edge('p', 'point', 'k', 'b')],
      ),
      registry,
    );
    expect(firstHandle(ev, 'k')).toBe('a');
    expect(dragPatches(ev, { nodeId: 'k', handle: 'b' }, [0, 2])).toEqual([
      { nodeId: 'p', params: { x: 0, y: 2 } },
    ]);
    expect(dragPatches(ev, { nodeId: 'k', handle: 'a' }, [-2, 0])).toEqual([
      { nodeId: 'k', params: { a: [-2, 0] } },
    ]);
  });

  it('still forwards to a hidden upstream point (no handle drawn, but it can move)', () => {
    const ev = evaluateGraph(
      doc(
        [node('p', 'point', { x: 1, y: 1, visible: false }), node('c', 'circle')],
        [edge('p', 'point', 'c', 'center')],
      ),
      registry,
    );
    expect(ev.scene.handles.some((h) => h.nodeId === 'p')).toBe(false);
    expect(dragPatches(ev, { nodeId: 'c', handle: 'center' }, [0, 0])).toEqual([
      { nodeId: 'p', params: { x: 0, y: 0 } },
    ]);
  });
});

describe('originalParams', () => {
  it('gives back the stored values, and the evaluated default for keys the document lacked', () => {
    const ev = evaluateGraph(
      doc([node('c', 'circle', { radius: 0.7 }), node('p', 'point', { x: 3 })]),
      registry,
    );
    expect(
      originalParams(ev, [
        { nodeId: 'c', params: { center: [1, 1], radius: 2 } },
        { nodeId: 'p', params: { x: 0, y: 0 } },
      ]),
    ).toEqual([
      { nodeId: 'c', params: { center: [0, 0], radius: 0.7 } },
      { nodeId: 'p', params: { x: 3, y: 0 } },
    ]);
  });
});
