import { defineNode } from '../core/define-node.ts';
import { VISIBLE } from './shared.ts';

export const pointNode = defineNode({
  type: 'point',
  version: 1,
  label: 'Point',
  category: 'Geometry',
  color: '#f2c14e',
  doc: 'A point (x, y); drag it in the render.',
  inputs: {
    x: { type: 'number', label: 'x', default: 0, step: 0.01 },
    y: { type: 'number', label: 'y', default: 0, step: 0.01 },
  },
  outputs: { point: { type: 'point', label: 'point' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => ({ outputs: { point: [inputs.x, inputs.y] } }),
  overlay: (_ctx, out) => [{ shape: 'point', at: out.point }],
  handles: (_ctx, out) => (out.point ? [{ handle: 'point', at: out.point }] : []),
  drag: (_h, to) => ({ x: to[0], y: to[1] }),
});
