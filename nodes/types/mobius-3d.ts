import { defineNode } from '../core/define-node.ts';
import type { NodeElement3d } from '../core/scene-3d.ts';
import { type Mobius3dType, mobius3d } from '../geometry/space/mobius-3d.ts';
import { fail } from './shared.ts';
import { dragSphereInput, sphereInput, sphereInputHandles, sphereProblem } from './space-shared.ts';

/** What the node shows for each type (docs/math-3d.md §2). */
export const MOBIUS_3D_READOUT: Readonly<Record<Mobius3dType, string>> = {
  hyperbolic: 'hyperbolic: the spheres are apart or nested',
  parabolic: 'parabolic: the spheres touch',
  elliptic: 'elliptic: the spheres cross (a rotation about their circle)',
};

export const mobius3dNode = defineNode({
  type: 'mobius-3d',
  version: 1,
  label: 'Möbius 3D (two spheres)',
  category: '3D',
  color: '#c2185b',
  doc: 'The generator G = I_S2∘I_S1 (invert in S1, then in S2) and its inverse; hyperbolic, parabolic or elliptic by how the spheres meet, shown on the node.',
  inputs: {
    s1: sphereInput('S1', [0, 0, 0], 1),
    s2: sphereInput('S2', [0.3, 0, 0], 2),
  },
  outputs: {
    element: { type: 'element3', label: 'element' },
    image: { type: 'sphere', label: "S1'", doc: 'I_S2(S1), the sphere G maps S1 onto' },
  },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const problem = sphereProblem(inputs.s1, 'S1') ?? sphereProblem(inputs.s2, 'S2');
    if (problem) return fail(problem);
    const g = mobius3d(inputs.s1, inputs.s2);
    if (!g.ok) return fail(g.error);
    const element: NodeElement3d = { kind: 'mobius-3d', nodeId, g: g.value };
    return {
      outputs: { element: [element], image: g.value.s1Image },
      readout: MOBIUS_3D_READOUT[g.value.type],
    };
  },
  overlay3d: ({ inputs }, out) => [
    { shape: 'sphere', sphere: inputs.s1 },
    { shape: 'sphere', sphere: inputs.s2 },
    { shape: 'sphere', sphere: out.image },
  ],
  handles3d: ({ inputs }) => [...sphereInputHandles('s1', inputs.s1), ...sphereInputHandles('s2', inputs.s2)],
  drag3d: (handle, to, { inputs }) =>
    handle.startsWith('s1.')
      ? dragSphereInput(handle, to, 's1', inputs.s1)
      : dragSphereInput(handle, to, 's2', inputs.s2),
});
