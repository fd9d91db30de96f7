import { defineNode } from '../core/define-node.ts';
import type { NodeElement3d } from '../core/scene-3d.ts';
import { compoundLoxodromic3d } from '../geometry/space/compound-loxodromic-3d.ts';
import { fail } from './shared.ts';
import {
  dragSphereInput,
  point3Input,
  sphereInput,
  sphereInputHandles,
  sphereProblem,
} from './space-shared.ts';

const CONTROLS = ['p', 'q1', 'q2'] as const;

export const compoundLoxodromic3dNode = defineNode({
  type: 'compound-loxodromic-3d',
  version: 1,
  label: 'Compound loxodromic 3D',
  category: '3D',
  color: '#c2185b',
  doc: 'The two-sphere generator with a twist: G = (I_S4∘I_S3)∘(I_S2∘I_S1), S3 and S4 the spheres through the control point P, its inverses in S1 and S2, and Q1 or Q2.',
  inputs: {
    s1: sphereInput('S1', [0, 0, 0], 1),
    s2: sphereInput('S2', [0.3, 0, 0], 2),
    p: point3Input('P', 0.5, 0.5, 0, 'control point: S3 and S4 pass through P and its inverses in S1 and S2'),
    q1: point3Input('Q1', 0, 0, 1.2, 'S3 passes through it'),
    q2: point3Input('Q2', 0.5, -0.5, 1, 'S4 passes through it; the angle between S3 and S4 sets the twist'),
  },
  outputs: {
    element: { type: 'element3', label: 'element' },
    s3: { type: 'sphere', label: 'S3' },
    s4: { type: 'sphere', label: 'S4' },
  },
  params: {},
  evaluate: ({ inputs: i, nodeId }) => {
    const problem = sphereProblem(i.s1, 'S1') ?? sphereProblem(i.s2, 'S2');
    if (problem) return fail(problem);
    const g = compoundLoxodromic3d(i.s1, i.s2, i.p, i.q1, i.q2);
    if (!g.ok) return fail(g.error);
    const element: NodeElement3d = { kind: 'compound-loxodromic-3d', nodeId, g: g.value };
    return {
      outputs: { element: [element], s3: g.value.s3, s4: g.value.s4 },
      readout: `base ${g.value.base.type}, twisted by S3, S4`,
    };
  },
  overlay3d: ({ inputs: i }, out) => [
    { shape: 'sphere', sphere: i.s1 },
    { shape: 'sphere', sphere: i.s2 },
    { shape: 'sphere', sphere: out.s3 },
    { shape: 'sphere', sphere: out.s4 },
    ...CONTROLS.map((k) => ({ shape: 'point' as const, at: i[k] })),
  ],
  handles3d: ({ inputs: i }) => [
    ...sphereInputHandles('s1', i.s1),
    ...sphereInputHandles('s2', i.s2),
    ...CONTROLS.map((k) => ({ handle: k, at: i[k] })),
  ],
  drag3d: (handle, to, { inputs: i }) => {
    if (CONTROLS.includes(handle as 'p')) return { [handle]: [...to] };
    return handle.startsWith('s1.')
      ? dragSphereInput(handle, to, 's1', i.s1)
      : dragSphereInput(handle, to, 's2', i.s2);
  },
});
