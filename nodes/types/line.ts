import { defineNode } from '../core/define-node.ts';
import type { Line } from '../core/values.ts';
import { isDegenerateLine } from '../geometry/circle.ts';
import { fail, pointInput, VISIBLE } from './shared.ts';

export const lineNode = defineNode({
  type: 'line',
  version: 1,
  label: 'Line',
  category: 'Geometry',
  color: '#4ecdc4',
  doc: 'The line through two points, directed from a to b (a mirror keeps its left side).',
  inputs: { a: pointInput('a', -1, 0), b: pointInput('b', 1, 0) },
  outputs: { line: { type: 'line', label: 'line' } },
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const line: Line = { a: inputs.a, b: inputs.b };
    if (isDegenerateLine(line)) return fail('the two points coincide: a line needs two distinct points');
    return { outputs: { line } };
  },
  overlay: (_ctx, out) => [{ shape: 'line', line: out.line }],
  handles: (_ctx, { line }) =>
    line
      ? [
          { handle: 'a', at: line.a },
          { handle: 'b', at: line.b },
        ]
      : [],
  drag: (handle, to) => ({ [handle]: [...to] }),
});
