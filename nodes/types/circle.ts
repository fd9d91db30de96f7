import { defineNode } from '../core/define-node.ts';
import { dist } from '../geometry/vec.ts';
import { fail, fmt, pointInput, VISIBLE } from './shared.ts';

export const circleNode = defineNode({
  type: 'circle',
  version: 1,
  label: 'Circle',
  category: 'Geometry',
  color: '#5b8def',
  doc: 'A circle from its centre and radius; drag the centre or the rim.',
  inputs: {
    center: pointInput('centre', 0, 0),
    radius: { type: 'number', label: 'radius', default: 1, min: 0, step: 0.01 },
  },
  outputs: { circle: { type: 'circle', label: 'circle' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const r = inputs.radius;
    if (!(r > 0)) return fail(`radius must be positive, got ${fmt(r)}`);
    return { outputs: { circle: { c: inputs.center, r } } };
  },
  overlay: (_ctx, out) => [{ shape: 'circle', circle: out.circle }],
  handles: (_ctx, out) => {
    if (!out.circle) return [];
    const { c, r } = out.circle;
    return [
      { handle: 'center', at: c },
      { handle: 'rim', at: [c[0] + r, c[1]] },
    ];
  },
  drag: (handle, to, ctx) =>
    handle === 'center' ? { center: [...to] } : { radius: Math.max(1e-6, dist(ctx.inputs.center, to)) },
});
