import { defineNode } from '../core/define-node.ts';
import type { InversionElement, OuterInversionElement } from '../core/scene-elements.ts';
import { fail, fmt } from './shared.ts';

export const inversionNode = defineNode({
  type: 'inversion',
  version: 1,
  label: 'Circle inversion',
  category: 'Generators',
  color: '#e85d75',
  doc: 'Inversion in a circle: a circular mirror that keeps the outside, mapping points inside out (flip keeps the inside).',
  inputs: { circle: { type: 'circle', label: 'circle', default: { c: [0, 0], r: 1 } } },
  outputs: { element: { type: 'element', label: 'element' } },
  params: {
    flip: { kind: 'boolean', default: false, label: 'flip', doc: 'keep the inside of the circle' },
  },
  // `flip` defaults to false, so a document saved before it existed keeps the outside, as it
  // always did: no new version and no migration needed.
  evaluate: ({ inputs, params, nodeId }) => {
    const { c, r } = inputs.circle;
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
