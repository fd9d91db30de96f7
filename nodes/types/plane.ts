import { defineNode } from '../core/define-node.ts';
import { add3, normalize3, sub3 } from '../geometry/space/vec3.ts';
import { fail, VISIBLE } from './shared.ts';
import { fmt3, planeProblem, point3Input } from './space-shared.ts';

export const planeNode = defineNode({
  type: 'plane',
  version: 1,
  label: 'Plane',
  category: '3D',
  color: '#2bb3a3',
  doc: 'The plane through a point with a normal; as a mirror it keeps the side the normal points to.',
  inputs: {
    point: point3Input('point', 0, 0, 0),
    normal: point3Input('normal', 0, 0, 1, 'points to the kept side (need not be unit length)'),
  },
  outputs: { plane: { type: 'plane', label: 'plane' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const plane = { point: inputs.point, normal: normalize3(inputs.normal) };
    const problem = planeProblem(plane);
    if (problem) return fail(problem);
    return { outputs: { plane }, readout: `normal ${fmt3(plane.normal)}` };
  },
  overlay3d: (_ctx, out) => [{ shape: 'plane', plane: out.plane }],
  handles3d: ({ inputs }) => [
    { handle: 'point', at: inputs.point },
    // At the tip of the normal as written, so a drag leaves the handle where it was dropped.
    { handle: 'normal', at: add3(inputs.point, inputs.normal) },
  ],
  drag3d: (handle, to, ctx) => {
    if (handle === 'point') return { point: [...to] };
    const normal = sub3(to, ctx.inputs.point);
    return normal.some((v) => v !== 0) ? { normal: [...normal] } : {};
  },
});
