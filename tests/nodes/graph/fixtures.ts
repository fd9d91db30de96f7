/** Test-only node types (never registered in the app) for evaluation paths real nodes cannot reach. */
import { defineNode } from '../../../nodes/core/define-node.ts';
import { createRegistry } from '../../../nodes/core/registry.ts';
import type { InversionElement } from '../../../nodes/core/scene.ts';
import { NODE_TYPES } from '../../../nodes/types/index.ts';

export const throwingNode = defineNode({
  type: 'test-throws',
  version: 1,
  label: 'Throws',
  category: 'Values',
  color: '#000000',
  doc: 'always throws',
  inputs: {},
  outputs: { value: { type: 'number' } },
  params: {},
  evaluate: () => {
    throw new Error('kaboom');
  },
});

export const nanNode = defineNode({
  type: 'test-nan',
  version: 1,
  label: 'NaN',
  category: 'Values',
  color: '#000000',
  doc: 'outputs a point with a NaN coordinate',
  inputs: {},
  outputs: { point: { type: 'point' } },
  params: {},
  evaluate: () => ({ outputs: { point: [0, Number.NaN] } }),
});

/** Emits `count` unit inversions at once (element limits) and reports the animation time. */
export const manyNode = defineNode({
  type: 'test-many',
  version: 1,
  label: 'Many',
  category: 'Generators',
  color: '#000000',
  doc: 'count inversions',
  inputs: { count: { type: 'number', default: 3, integer: true, min: 0 } },
  outputs: { element: { type: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId, time }) => ({
    outputs: {
      element: Array.from(
        { length: inputs.count as number },
        (_, i): InversionElement => ({ kind: 'inversion', nodeId, c: [i, 0], r: 0.25 }),
      ),
    },
    readout: `t = ${time}`,
  }),
});

export const testRegistry = createRegistry([...NODE_TYPES, throwingNode, nanNode, manyNode]);
