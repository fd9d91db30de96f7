import { defineNode } from '../core/define-node.ts';
import type { ParallelMirrorsElement } from '../core/scene-elements.ts';
import { fail, fmt, pointInput } from './shared.ts';

/** Smallest side a drag may set, so the rectangle never collapses while dragging. */
const MIN_SIDE = 1e-3;

export const rectangleKaleidoscopeNode = defineNode({
  type: 'rectangle-kaleidoscope',
  version: 1,
  label: 'Rectangle kaleidoscope',
  category: 'Kaleidoscopes',
  color: '#c06c84',
  doc: 'The four mirrors of a rectangle (symmetry *2222): the rectangle is the tile, reflected across the plane.',
  inputs: {
    corner: pointInput('corner', -0.5, -0.375),
    width: { type: 'number', label: 'width', default: 1, min: 0, step: 0.01 },
    height: { type: 'number', label: 'height', default: 0.75, min: 0, step: 0.01 },
  },
  outputs: { elements: { type: 'element', label: 'mirrors' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { corner: q, width: a, height: b } = inputs;
    if (!(a > 0 && b > 0))
      return fail(`the rectangle needs a positive width and height, got ${fmt(a)} × ${fmt(b)}`);
    // Opposite sides are parallel mirror pairs: each pair folds in closed form (depth = mirrors crossed).
    const across: ParallelMirrorsElement = { kind: 'parallel-mirrors', nodeId, q, n: [1, 0], period: a };
    const up: ParallelMirrorsElement = { kind: 'parallel-mirrors', nodeId, q, n: [0, 1], period: b };
    return { outputs: { elements: [across, up] }, readout: `*2222: ${fmt(a)} × ${fmt(b)}` };
  },
  overlay: (ctx) => {
    const [x0, y0] = ctx.inputs.corner;
    const x1 = x0 + ctx.inputs.width;
    const y1 = y0 + ctx.inputs.height;
    return [
      { shape: 'line', line: { a: [x0, y0], b: [x1, y0] } },
      { shape: 'line', line: { a: [x1, y0], b: [x1, y1] } },
      { shape: 'line', line: { a: [x1, y1], b: [x0, y1] } },
      { shape: 'line', line: { a: [x0, y1], b: [x0, y0] } },
    ];
  },
  handles: (ctx) => {
    const [x0, y0] = ctx.inputs.corner;
    return [
      { handle: 'corner', at: [x0, y0] },
      { handle: 'opposite', at: [x0 + ctx.inputs.width, y0 + ctx.inputs.height] },
    ];
  },
  drag: (handle, to, ctx) => {
    if (handle === 'corner') return { corner: [...to] };
    const [x0, y0] = ctx.inputs.corner;
    return { width: Math.max(MIN_SIDE, to[0] - x0), height: Math.max(MIN_SIDE, to[1] - y0) };
  },
});
