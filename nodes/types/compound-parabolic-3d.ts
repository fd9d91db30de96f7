import { defineNode } from '../core/define-node.ts';
import type { NodeElement3d } from '../core/scene-3d.ts';
import { compoundParabolic3d } from '../geometry/space/compound-parabolic-3d.ts';
import { dot3, sub3 } from '../geometry/space/vec3.ts';
import { degrees, fail, fmt } from './shared.ts';
import { dragPlaneInput, planeInput, planeInputHandles, planeProblem } from './space-shared.ts';

/** How far from exactly opposite the two normals may be (1 − cos of the angle between −n1 and n2). */
const FACING_TOLERANCE = 1e-9;

export const compoundParabolic3dNode = defineNode({
  type: 'compound-parabolic-3d',
  version: 1,
  label: 'Compound parabolic 3D',
  category: '3D',
  color: '#c2185b',
  doc: 'Two facing parallel planes (normals towards each other) translate space by twice their gap; the torsion turns each step about the axis through P1’s point.',
  inputs: {
    p1: planeInput('P1', [0, 0, -1], [0, 0, 1]),
    p2: planeInput('P2', [0, 0, 1], [0, 0, -1]),
    torsion: {
      type: 'number',
      label: 'torsion °',
      default: 0,
      step: 1,
      doc: 'rotation about the axis per translation',
    },
  },
  outputs: { element: { type: 'element3', label: 'element' } },
  params: {},
  evaluate: ({ inputs: i, nodeId }) => {
    const problem = planeProblem(i.p1, 'P1') ?? planeProblem(i.p2, 'P2');
    if (problem) return fail(problem);
    const n = i.p1.normal;
    if (1 + dot3(n, i.p2.normal) > FACING_TOLERANCE)
      return fail('P1 and P2 must be parallel with normals facing each other (P2’s normal = −P1’s normal)');
    const gap = dot3(sub3(i.p2.point, i.p1.point), n);
    if (!(gap > 0))
      return fail('P2 must lie on the side P1’s normal points to (the planes face each other across a gap)');
    const g = compoundParabolic3d(i.p1.point, n, gap, (i.torsion * Math.PI) / 180);
    if (!g.ok) return fail(g.error);
    const element: NodeElement3d = { kind: 'compound-parabolic-3d', nodeId, g: g.value };
    return {
      outputs: { element: [element] },
      readout: `translation ${fmt(2 * gap)}, turn ${degrees(g.value.torsion)}`,
    };
  },
  overlay3d: ({ inputs: i }) => [
    { shape: 'plane', plane: i.p1 },
    { shape: 'plane', plane: i.p2 },
  ],
  handles3d: ({ inputs: i }) => [...planeInputHandles('p1', i.p1), ...planeInputHandles('p2', i.p2)],
  drag3d: (handle, to, { inputs: i }) =>
    handle.startsWith('p1.')
      ? dragPlaneInput(handle, to, 'p1', i.p1)
      : dragPlaneInput(handle, to, 'p2', i.p2),
});
