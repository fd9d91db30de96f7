import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { MaskitSliceElement } from '../core/scene-elements.ts';
import { belowMaskitBoundary, MASKIT_MAX_DENOMINATOR, maskitCusps } from '../geometry/maskit-cusps.ts';
import { fmt, pointInput } from './shared.ts';

/** Landmark cusps marked as points over the picture (each with its translate by 2). */
const MARKED = new Set(['0/1', '1/2', '1/3', '2/3']);

export const maskitSliceNode = defineNode({
  type: 'maskit-slice',
  version: 1,
  label: 'Maskit slice',
  category: 'Generators',
  color: '#e85d75',
  doc: 'The parameter plane of the Maskit group: each point μ is painted by whether the group of that μ is discrete and free (above the fractal boundary through the cusps) or not (the limit colour). Click or drag to choose μ, and wire μ into a Maskit group node.',
  inputs: {
    mu: {
      ...pointInput('μ', 0.2, 1.95),
      doc: 'the chosen parameter μ: click anywhere in the render, or drag its handle',
    },
  },
  outputs: {
    element: { type: 'element', label: 'element' },
    mu: { type: 'point', label: 'μ' },
  },
  params: {
    maxDenominator: {
      kind: 'number',
      default: MASKIT_MAX_DENOMINATOR,
      min: 1,
      max: MASKIT_MAX_DENOMINATOR,
      integer: true,
      label: 'cusps up to q',
      doc: 'the boundary is drawn through the cusps p/q with q up to this; fewer show how the polyline approaches the fractal',
    },
  },
  evaluate: ({ inputs, params, nodeId }) => {
    const mu = inputs.mu;
    const element: MaskitSliceElement = {
      kind: 'maskit-slice',
      nodeId,
      maxDenominator: params.maxDenominator,
    };
    const outside = belowMaskitBoundary(mu[0], mu[1], params.maxDenominator);
    const shown = `${fmt(mu[0])} ${mu[1] < 0 ? '−' : '+'} ${fmt(Math.abs(mu[1]))}i`;
    return {
      outputs: { element: [element], mu },
      readout: `μ = ${shown}: ${outside ? 'outside the slice (not discrete)' : 'in the slice (discrete, free)'}`,
      diagnostics: outside ? [diag('outsideMaskitSlice', { port: 'mu' }, shown)] : [],
    };
  },
  /** A few named cusps of the shown period, so the boundary's landmarks can be found. */
  overlay: ({ params }) =>
    maskitCusps()
      .filter((c) => c.q <= params.maxDenominator && MARKED.has(`${c.p}/${c.q}`))
      .flatMap((c) => [0, 2].map((k) => ({ shape: 'point' as const, at: [c.mu[0] + k, c.mu[1]] as const }))),
  handles: ({ inputs }) => [{ handle: 'mu', at: inputs.mu, placeOnClick: true }],
  drag: (_handle, to) => ({ mu: [...to] }),
});
