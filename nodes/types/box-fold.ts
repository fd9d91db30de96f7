import { defineNode } from '../core/define-node.ts';
import type { NodeElement3d } from '../core/scene-3d.ts';
import { scale3 } from '../geometry/space/vec3.ts';
import { fail } from './shared.ts';
import { boxHandles, boxProblem, dragBox, fmt3, point3Input } from './space-shared.ts';

/**
 * The box fold of docs/math-3d.md §10: with a sphere inversion after it, the artists'
 * pseudo-Kleinian (paper Fig. 38).
 */
export const boxFoldNode = defineNode({
  type: 'box-fold',
  version: 1,
  label: 'Box fold',
  category: '3D',
  color: '#c2185b',
  doc: 'Folds space into an axis-aligned box by reflecting in its six faces (a repeating lattice of mirrored boxes); followed by a sphere inversion it makes a pseudo-Kleinian (Fig. 38).',
  inputs: {
    center: point3Input('centre', 0, 0, 0),
    halfSize: point3Input('half size', 1, 1, 1, 'half the box’s extent along x, y and z'),
  },
  outputs: { element: { type: 'element3', label: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const problem = boxProblem(inputs.halfSize);
    if (problem) return fail(problem);
    if (!inputs.center.every(Number.isFinite)) return fail('the box’s centre is not finite (NaN or ∞)');
    const element: NodeElement3d = {
      kind: 'box-fold',
      nodeId,
      box: { center: inputs.center, halfSize: inputs.halfSize },
    };
    return {
      outputs: { element: [element] },
      readout: `lattice period ${fmt3(scale3(inputs.halfSize, 4))}`,
    };
  },
  overlay3d: ({ inputs }) => [{ shape: 'box', center: inputs.center, halfSize: inputs.halfSize }],
  handles3d: ({ inputs }) => boxHandles(inputs.center, inputs.halfSize),
  /** The corner sets the half size: its offset from the centre per axis (kept positive). */
  drag3d: (handle, to, ctx) => dragBox(handle, to, ctx.inputs.center),
});
