import { defineNode } from '../core/define-node.ts';
import type { NodeElement3d } from '../core/scene-3d.ts';
import { fail, fmt } from './shared.ts';
import { dragSphereInput, sphereInput, sphereInputHandles, sphereProblem } from './space-shared.ts';

export const sphereInversionNode = defineNode({
  type: 'sphere-inversion',
  version: 1,
  label: 'Sphere inversion',
  category: '3D',
  color: '#c2185b',
  doc: 'Inversion in a sphere: a spherical mirror that keeps the outside and maps the ball inside out.',
  inputs: { sphere: sphereInput('sphere', [0, 0, 0], 1) },
  outputs: { element: { type: 'element3', label: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const problem = sphereProblem(inputs.sphere);
    if (problem) return fail(problem);
    const element: NodeElement3d = { kind: 'sphere-inversion', nodeId, sphere: inputs.sphere };
    return { outputs: { element: [element] }, readout: `r = ${fmt(inputs.sphere.radius)}` };
  },
  overlay3d: ({ inputs }) => [{ shape: 'sphere', sphere: inputs.sphere }],
  handles3d: ({ inputs }) => sphereInputHandles('sphere', inputs.sphere),
  drag3d: (handle, to, ctx) => dragSphereInput(handle, to, 'sphere', ctx.inputs.sphere),
});
