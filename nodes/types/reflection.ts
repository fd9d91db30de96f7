import { defineNode } from '../core/define-node.ts';
import type { ReflectionElement } from '../core/scene-elements.ts';
import { isDegenerateLine, lineNormal } from '../geometry/circle.ts';
import { fail } from './shared.ts';

export const reflectionNode = defineNode({
  type: 'reflection',
  version: 1,
  label: 'Line reflection',
  category: 'Generators',
  color: '#e85d75',
  doc: "Reflection in a line: a straight mirror that keeps the line's left side (flip keeps the right).",
  inputs: { line: { type: 'line', label: 'line', default: { a: [0, 0], b: [1, 0] } } },
  outputs: { element: { type: 'element', label: 'element' } },
  params: {
    flip: { kind: 'boolean', default: false, label: 'flip', doc: 'keep the other side of the line' },
  },
  evaluate: ({ inputs, params, nodeId }) => {
    const line = inputs.line;
    if (isDegenerateLine(line)) return fail('the line has no direction (its two points coincide)');
    const n = lineNormal(line);
    const element: ReflectionElement = {
      kind: 'reflection',
      nodeId,
      q: line.a,
      n: params.flip ? [-n[0], -n[1]] : n,
    };
    return { outputs: { element: [element] } };
  },
});
