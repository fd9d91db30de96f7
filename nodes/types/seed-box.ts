import { defineNode } from '../core/define-node.ts';
import type { Seed3d } from '../core/scene-3d.ts';
import { MATERIAL_PARAM, REFLECTIVITY_INPUT, withMaterial } from './seed-material.ts';
import { fail } from './shared.ts';
import { boxHandles, boxProblem, dragBox, fmt3, point3Input } from './space-shared.ts';

export const seedBoxNode = defineNode({
  type: 'seed-box',
  version: 1,
  label: 'Seed box',
  category: '3D',
  color: '#ba68c8',
  doc: 'A 3D orbit seed: an axis-aligned box (centre, half size along x, y, z); the 3D render draws it and all its images (the paper’s Fig. 24).',
  inputs: {
    center: point3Input('centre', 0, 0, 0),
    halfSize: point3Input('half size', 0.4, 0.4, 0.4, 'half the box’s extent along x, y and z'),
    color: { type: 'color', label: 'colour', default: '#f4a259' },
    reflectivity: REFLECTIVITY_INPUT,
  },
  outputs: { seed: { type: 'seed3', label: 'seed' } },
  params: { material: MATERIAL_PARAM },
  evaluate: ({ inputs, params, nodeId }) => {
    const problem = boxProblem(inputs.halfSize);
    if (problem) return fail(problem);
    const plain: Seed3d = {
      kind: 'box',
      nodeId,
      center: inputs.center,
      halfSize: inputs.halfSize,
      color: inputs.color,
    };
    const { seed, diagnostics } = withMaterial(plain, params.material, inputs.reflectivity);
    return { outputs: { seed }, diagnostics, readout: `half size ${fmt3(inputs.halfSize)}` };
  },
  overlay3d: (_ctx, out) =>
    out.seed.kind === 'box' ? [{ shape: 'box', center: out.seed.center, halfSize: out.seed.halfSize }] : [],
  handles3d: ({ inputs }) => boxHandles(inputs.center, inputs.halfSize),
  /** The corner sets the half size: its offset from the centre per axis (kept positive). */
  drag3d: (handle, to, ctx) => dragBox(handle, to, ctx.inputs.center),
});
