import { defineNode } from '../core/define-node.ts';
import type { InversionElement } from '../core/scene-elements.ts';
import { fail, fmt } from './shared.ts';

export const inversionNode = defineNode({
  type: 'inversion',
  version: 1,
  label: 'Circle inversion',
  category: 'Generators',
  color: '#e85d75',
  doc: 'Inversion in a circle: points inside are mapped outside (a circular mirror).',
  inputs: { circle: { type: 'circle', label: 'circle', default: { c: [0, 0], r: 1 } } },
  outputs: { element: { type: 'element', label: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { c, r } = inputs.circle;
    if (!(r > 0)) return fail(`the circle's radius must be positive, got ${fmt(r)}`);
    const element: InversionElement = { kind: 'inversion', nodeId, c, r };
    return { outputs: { element: [element] } };
  },
});
