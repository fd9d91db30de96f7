import { defineNode } from '../core/define-node.ts';
import { VISIBLE } from './shared.ts';
import { fmt3 } from './space-shared.ts';

export const point3dNode = defineNode({
  type: 'point-3d',
  version: 1,
  label: 'Point 3D',
  category: '3D',
  color: '#f7dc6f',
  doc: 'A point of space (x, y, z; z is up); drag it in the 3D view.',
  inputs: {
    x: { type: 'number', label: 'x', default: 0, step: 0.01 },
    y: { type: 'number', label: 'y', default: 0, step: 0.01 },
    z: { type: 'number', label: 'z', default: 0, step: 0.01 },
  },
  outputs: { point: { type: 'point3', label: 'point' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const point = [inputs.x, inputs.y, inputs.z] as const;
    return { outputs: { point }, readout: fmt3(point) };
  },
  overlay3d: (_ctx, out) => [{ shape: 'point', at: out.point }],
  handles3d: ({ inputs }) => [{ handle: 'point', at: [inputs.x, inputs.y, inputs.z] }],
  drag3d: (_h, to) => ({ x: to[0], y: to[1], z: to[2] }),
});
