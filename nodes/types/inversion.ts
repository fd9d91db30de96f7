import { defineNode } from '../core/define-node.ts';
import type { InversionElement, OuterInversionElement } from '../core/scene.ts';
import type { Circle } from '../core/values.ts';
import { fail, fmt } from './shared.ts';

export const inversionNode = defineNode({
  type: 'inversion',
  version: 2,
  label: 'Circle inversion',
  category: 'Generators',
  color: '#e85d75',
  doc: 'Inversion in a circle: a circular mirror that keeps the outside, mapping points inside out (flip keeps the inside).',
  inputs: { circle: { type: 'circle', label: 'circle', default: { c: [0, 0], r: 1 } } },
  outputs: { element: { type: 'element', label: 'element' } },
  params: {
    flip: { kind: 'boolean', default: false, label: 'flip', doc: 'keep the inside of the circle' },
  },
  // Version 2 added `flip`: a version-1 node keeps the outside, as it always did (a `flip` already
  // there — a hand-written file that gives no version — is kept).
  migrations: { 1: (params) => ({ flip: false, ...params }) },
  evaluate: ({ inputs, params, nodeId }) => {
    const { c, r } = inputs.circle as Circle;
    if (!(r > 0)) return fail(`the circle's radius must be positive, got ${fmt(r)}`);
    const element: InversionElement | OuterInversionElement = {
      kind: params.flip ? 'outer-inversion' : 'inversion',
      nodeId,
      c,
      r,
    };
    return { outputs: { element: [element] } };
  },
});
