import { defineNode } from '../core/define-node.ts';
import { sphereFromFourPoints } from '../geometry/space/sphere.ts';
import { fail, fmt, VISIBLE } from './shared.ts';
import { fmt3, point3Input } from './space-shared.ts';

const CORNERS = ['a', 'b', 'c', 'd'] as const;

export const sphere4ptNode = defineNode({
  type: 'sphere-4pt',
  version: 1,
  label: 'Sphere through 4 points',
  category: '3D',
  color: '#3fa7d6',
  doc: 'The sphere through four points (they must not lie in one plane); drag any of them.',
  inputs: {
    a: point3Input('a', 1, 0, 0),
    b: point3Input('b', 0, 1, 0),
    c: point3Input('c', 0, 0, 1),
    d: point3Input('d', -1, 0, 0),
  },
  outputs: { sphere: { type: 'sphere', label: 'sphere' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const s = sphereFromFourPoints(inputs.a, inputs.b, inputs.c, inputs.d);
    if (!s.ok) return fail(s.error);
    return { outputs: { sphere: s.value }, readout: `${fmt3(s.value.center)}, r = ${fmt(s.value.radius)}` };
  },
  overlay3d: ({ inputs }, out) => [
    { shape: 'sphere', sphere: out.sphere },
    ...CORNERS.map((k) => ({ shape: 'point' as const, at: inputs[k] })),
  ],
  handles3d: ({ inputs }) => CORNERS.map((k) => ({ handle: k, at: inputs[k] })),
  drag3d: (handle, to) => (CORNERS.includes(handle as 'a') ? { [handle]: [...to] } : {}),
});
