import { defineNode } from '../core/define-node.ts';
import type { Circle } from '../core/values.ts';
import { GEOMETRY_EPS } from '../geometry/circle.ts';
import { dist } from '../geometry/vec.ts';
import { pointHandles } from './construction-shared.ts';
import { fail, pointInput, VISIBLE } from './shared.ts';

export const circleCenterPointNode = defineNode({
  type: 'circle-center-point',
  version: 1,
  label: 'Circle through a point',
  category: 'Geometry',
  color: '#5b8def',
  doc: 'The circle with a given centre passing through a point (radius = their distance).',
  inputs: { center: pointInput('centre', 0, 0), through: pointInput('through', 1, 0) },
  outputs: { circle: { type: 'circle', label: 'circle' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const c = inputs.center;
    const r = dist(c, inputs.through);
    if (!(r > GEOMETRY_EPS * Math.max(1, Math.hypot(...c))))
      return fail('the centre and the point coincide: the radius would be 0');
    return { outputs: { circle: { c, r } satisfies Circle } };
  },
  overlay: (_ctx, out) => [{ shape: 'circle', circle: out.circle }],
  ...pointHandles('center', 'through'),
});
