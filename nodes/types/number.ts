import { defineNode } from '../core/define-node.ts';

export const numberNode = defineNode({
  type: 'number',
  version: 1,
  label: 'Number',
  category: 'Values',
  color: '#9aa5b1',
  doc: 'A constant number to wire into any number input.',
  inputs: { value: { type: 'number', label: 'value', default: 1 } },
  outputs: { value: { type: 'number', label: 'value' } },
  params: {},
  evaluate: ({ inputs }) => ({ outputs: { value: inputs.value } }),
});
