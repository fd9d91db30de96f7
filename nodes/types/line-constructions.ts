/** Lines constructed from points and lines: perpendicular bisector, parallel and perpendicular. */
import { defineNode, type InputSpec, type OutputSpecs } from '../core/define-node.ts';
import type { Line, Vec2 } from '../core/values.ts';
import { isDegenerateLine } from '../geometry/circle.ts';
import { lerp, nearlyEqual, perp, sub } from '../geometry/vec.ts';
import { lineAlong, pointHandles } from './construction-shared.ts';
import { fail, pointInput, VISIBLE } from './shared.ts';

const lineOut = { line: { type: 'line', label: 'line' } } as const satisfies OutputSpecs;
const lineOverlay = (_ctx: unknown, out: { readonly line: Line }) => [
  { shape: 'line' as const, line: out.line },
];
const lineIn = {
  type: 'line',
  label: 'line',
  default: { a: [-1, -0.5], b: [1, 0.5] },
} as const satisfies InputSpec;
const noLine = 'the line has no direction (its two points coincide)';

export const perpendicularBisectorNode = defineNode({
  type: 'perpendicular-bisector',
  version: 1,
  label: 'Perpendicular bisector',
  category: 'Construction',
  color: '#4ecdc4',
  doc: 'The line of points equally far from a and b (through their midpoint, at right angles; it keeps the side of a).',
  inputs: { a: pointInput('a', -1, 0), b: pointInput('b', 1, 0) },
  outputs: lineOut,
  params: { visible: VISIBLE },
  evaluate: ({ inputs }) => {
    const { a, b } = inputs;
    if (nearlyEqual(a, b, 1e-12 * Math.max(1, Math.hypot(...a))))
      return fail('a and b coincide: every line through them bisects');
    return { outputs: { line: lineAlong(lerp(a, b, 0.5), perp(sub(b, a))) } };
  },
  overlay: lineOverlay,
  ...pointHandles('a', 'b'),
});

/**
 * The line through a point whose direction is a given line's direction d turned by `turn`
 * (identity: parallel; perp, d ↦ (−d_y, d_x): perpendicular).
 */
function lineThroughPoint(type: string, label: string, doc: string, turn: (d: Vec2) => Vec2) {
  return defineNode({
    type,
    version: 1,
    label,
    category: 'Construction',
    color: '#4ecdc4',
    doc,
    inputs: { line: lineIn, point: pointInput('through', 0, 1) },
    outputs: lineOut,
    params: { visible: VISIBLE },
    evaluate: ({ inputs }) => {
      const { line, point } = inputs;
      if (isDegenerateLine(line)) return fail(noLine);
      return { outputs: { line: lineAlong(point, turn(sub(line.b, line.a))) } };
    },
    overlay: lineOverlay,
    ...pointHandles('point'),
  });
}

export const parallelLineNode = lineThroughPoint(
  'parallel-line',
  'Parallel line',
  'The line through a point parallel to a line (same direction).',
  (d) => d,
);

export const perpendicularLineNode = lineThroughPoint(
  'perpendicular-line',
  'Perpendicular line',
  "The line through a point at right angles to a line (its direction is the line's turned by +90°).",
  perp,
);
