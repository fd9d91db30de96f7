import { defineNode } from '../core/define-node.ts';
import type { NodeElement3d } from '../core/scene-3d.ts';
import { fail } from './shared.ts';
import { dragPlaneInput, fmt3, planeInput, planeInputHandles, planeProblem } from './space-shared.ts';

export const planeReflectionNode = defineNode({
  type: 'plane-reflection',
  version: 1,
  label: 'Plane reflection',
  category: '3D',
  color: '#c2185b',
  doc: 'Reflection in a plane: a flat mirror that keeps the side its normal points to and reflects the other.',
  inputs: { plane: planeInput('plane', [0, 0, 0], [0, 0, 1]) },
  outputs: { element: { type: 'element3', label: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const problem = planeProblem(inputs.plane);
    if (problem) return fail(problem);
    const element: NodeElement3d = { kind: 'plane-reflection', nodeId, plane: inputs.plane };
    return { outputs: { element: [element] }, readout: `keeps the side of ${fmt3(inputs.plane.normal)}` };
  },
  overlay3d: ({ inputs }) => [{ shape: 'plane', plane: inputs.plane }],
  handles3d: ({ inputs }) => planeInputHandles('plane', inputs.plane),
  drag3d: (handle, to, ctx) => dragPlaneInput(handle, to, 'plane', ctx.inputs.plane),
});
