import { defineNode } from '../core/define-node.ts';
import { circleThrough3 } from '../geometry/circle.ts';
import { fail, pointInput, VISIBLE } from './shared.ts';

export const circle3ptNode = defineNode({
  type: 'circle-3pt',
  version: 1,
  label: 'Circle through 3 points',
  category: 'Geometry',
  color: '#5b8def',
  doc: 'The circle through three points (they must not be collinear).',
  inputs: { a: pointInput('a', -1, 0), b: pointInput('b', 0, 1), c: pointInput('c', 1, 0) },
  outputs: { circle: { type: 'circle', label: 'circle' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const circle = circleThrough3(inputs.a, inputs.b, inputs.c);
    if (!circle) return fail('the three points are collinear (or coincide): no circle passes through them');
    return { outputs: { circle } };
  },
  overlay: (ctx, out) => [
    { shape: 'circle', circle: out.circle },
    ...(['a', 'b', 'c'] as const).map((k) => ({ shape: 'point' as const, at: ctx.inputs[k] })),
  ],
  handles: (ctx) => (['a', 'b', 'c'] as const).map((k) => ({ handle: k, at: ctx.inputs[k] })),
  drag: (handle, to) => ({ [handle]: [...to] }),
});
