import { defineNode } from '../core/define-node.ts';
import type { Seed3d } from '../core/scene-3d.ts';
import { MATERIAL_PARAM, REFLECTIVITY_INPUT, withMaterial } from './seed-material.ts';
import { fail, fmt } from './shared.ts';
import { point3Input, radiusTo, sphereHandles, sphereProblem } from './space-shared.ts';

export const seedSphereNode = defineNode({
  type: 'seed-sphere',
  version: 1,
  label: 'Seed sphere',
  category: '3D',
  color: '#ba68c8',
  doc: 'A 3D orbit seed: a coloured ball; the 3D render draws it and all its images (the paper’s Figs. 11–12). Keep it outside every region the elements move.',
  inputs: {
    center: point3Input('centre', 0, 0, 0),
    radius: { type: 'number', label: 'radius', default: 0.5, step: 0.01 },
    color: { type: 'color', label: 'colour', default: '#7bd389' },
    reflectivity: REFLECTIVITY_INPUT,
  },
  outputs: { seed: { type: 'seed3', label: 'seed' } },
  params: { material: MATERIAL_PARAM },
  evaluate: ({ inputs, params, nodeId }) => {
    const sphere = { center: inputs.center, radius: inputs.radius };
    const problem = sphereProblem(sphere, 'the seed sphere');
    if (problem) return fail(problem);
    const plain: Seed3d = { kind: 'sphere', nodeId, sphere, color: inputs.color };
    const { seed, diagnostics } = withMaterial(plain, params.material, inputs.reflectivity);
    return { outputs: { seed }, diagnostics, readout: `r = ${fmt(inputs.radius)}` };
  },
  overlay3d: (_ctx, out) =>
    out.seed.kind === 'sphere' ? [{ shape: 'sphere', sphere: out.seed.sphere }] : [],
  handles3d: ({ inputs }) => sphereHandles({ center: inputs.center, radius: Math.max(0, inputs.radius) }),
  drag3d: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { radius: radiusTo(ctx.inputs.center, to) },
});
