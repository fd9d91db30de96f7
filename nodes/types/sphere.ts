import { defineNode } from '../core/define-node.ts';
import { fail, fmt, VISIBLE } from './shared.ts';
import { fmt3, point3Input, radiusTo, sphereHandles, sphereProblem } from './space-shared.ts';

export const sphereNode = defineNode({
  type: 'sphere',
  version: 1,
  label: 'Sphere',
  category: '3D',
  color: '#3fa7d6',
  doc: 'A sphere from its centre and radius; drag the centre or a point on it.',
  inputs: {
    center: point3Input('centre', 0, 0, 0),
    radius: { type: 'number', label: 'radius', default: 1, step: 0.01 },
  },
  outputs: { sphere: { type: 'sphere', label: 'sphere' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const sphere = { center: inputs.center, radius: inputs.radius };
    const problem = sphereProblem(sphere);
    if (problem) return fail(problem);
    return { outputs: { sphere }, readout: `${fmt3(sphere.center)}, r = ${fmt(sphere.radius)}` };
  },
  overlay3d: (_ctx, out) => [{ shape: 'sphere', sphere: out.sphere }],
  // From the inputs, so a sphere with a bad radius can still be dragged back into shape.
  handles3d: ({ inputs }) => sphereHandles({ center: inputs.center, radius: Math.max(0, inputs.radius) }),
  drag3d: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { radius: radiusTo(ctx.inputs.center, to) },
});
