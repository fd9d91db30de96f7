import { defineNode } from '../core/define-node.ts';
import type { SpiralSimilarityElement } from '../core/scene-elements.ts';
import type { Circle } from '../core/values.ts';
import { dist } from '../geometry/vec.ts';
import { angleInput } from './construction-shared.ts';
import { fail, fmt, pointInput } from './shared.ts';

/** A drag keeps r1 < r2 by at least this factor, so the node stays valid while dragging. */
const GAP = 1.01;

export const spiralSimilarityNode = defineNode({
  type: 'spiral-similarity',
  version: 1,
  label: 'Spiral similarity',
  category: 'Generators',
  color: '#e85d75',
  doc: 'Scale by (r2/r1)² and turn by 2φ about a centre, folded in one step: the annulus r1 ≤ |p − c| < r2²/r1 is the tile (a Doyle-style spiral).',
  inputs: {
    center: pointInput('centre', 0, 0),
    r1: { type: 'number', label: 'r1', default: 0.5, min: 0, step: 0.01, doc: 'inner mirror circle' },
    r2: {
      type: 'number',
      label: 'r2',
      default: 0.8,
      min: 0,
      step: 0.01,
      doc: 'outer mirror circle (r2 > r1)',
    },
    angle: angleInput('φ (°)', 15, 'angle between the two mirror lines; each step turns by 2φ'),
  },
  outputs: { element: { type: 'element', label: 'element' } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { center: c, r1, r2, angle: phi } = inputs;
    if (!(r1 > 0)) return fail(`r1 must be positive, got ${fmt(r1)}`);
    if (!(r2 > r1))
      return fail(
        `r2 must be larger than r1 (got r1 = ${fmt(r1)}, r2 = ${fmt(r2)}): the annulus would be empty`,
      );
    const element: SpiralSimilarityElement = {
      kind: 'spiral-similarity',
      nodeId,
      c,
      r1,
      r2,
      angle: (phi * Math.PI) / 180,
    };
    return {
      outputs: { element: [element] },
      readout: `each step: scale ×${fmt((r2 / r1) ** 2)}, turn ${fmt(2 * phi)}°`,
    };
  },
  overlay: (ctx) => {
    const { center: c, r1, r2 } = ctx.inputs;
    // The tile annulus: r1 ≤ |p − c| < r2²/r1.
    return [
      { shape: 'point', at: c },
      { shape: 'circle', circle: { c, r: r1 } satisfies Circle },
      { shape: 'circle', circle: { c, r: (r2 * r2) / r1 } satisfies Circle },
    ];
  },
  handles: (ctx) => {
    const { center: c, r1, r2 } = ctx.inputs;
    return [
      { handle: 'center', at: c },
      { handle: 'r1', at: [c[0] + r1, c[1]] },
      { handle: 'r2', at: [c[0] + r2, c[1]] },
    ];
  },
  drag: (handle, to, ctx) => {
    const { center: c, r1, r2 } = ctx.inputs;
    const r = dist(c, to);
    if (handle === 'center') return { center: [...to] };
    if (handle === 'r1') return { r1: Math.max(1e-6, Math.min(r, r2 / GAP)) };
    return { r2: Math.max(r, r1 * GAP) };
  },
});
