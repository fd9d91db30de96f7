import { defineNode } from '../core/define-node.ts';
import type { MaskitElement } from '../core/scene-elements.ts';
import { fail, fmt, pointInput } from './shared.ts';

/**
 * Whether the isometric circles |z − 2k| = 1 and |z − μ − 2m| = 1 are disjoint or tangent: then
 * they bound a true Ford domain and the picture is exact (docs/math.md "The Maskit slice"). The
 * nearest translate of μ to 0 decides: |μ − 2m| ≥ 2 with m = round(Re μ / 2).
 */
export const maskitCirclesDisjoint = (mu: readonly [number, number]): boolean =>
  Math.hypot(mu[0] - 2 * Math.round(mu[0] / 2), mu[1]) >= 2 - 1e-12;

export const maskitNode = defineNode({
  type: 'maskit',
  version: 1,
  label: 'Maskit group',
  category: 'Generators',
  color: '#e85d75',
  doc: 'The Maskit group of a: z ↦ μ + 1/z and the translation by 2, drawn by Jos Leys’s method: its limit set, the tangent-circle fractals of the Maskit slice. Drag μ in the picture.',
  inputs: {
    mu: {
      ...pointInput('μ', 0, 2),
      doc: 'the parameter μ = x + iy (y > 0); the Maskit slice is the region above a fractal curve through 2i',
    },
  },
  outputs: {
    element: { type: 'element', label: 'element' },
    mu: { type: 'point', label: 'μ' },
  },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const mu = inputs.mu;
    if (!(mu[1] > 0))
      return fail(`Im μ must be positive (the group's strip is 0 < Im z < Im μ), got ${fmt(mu[1])}`);
    const element: MaskitElement = { kind: 'maskit', nodeId, mu: [mu[0], mu[1]] };
    const sign = mu[0] < 0 ? '−' : '+';
    const exact = maskitCirclesDisjoint(mu)
      ? 'isometric circles disjoint: exact'
      : 'circles overlap: near the slice boundary, or outside it (not discrete)';
    return {
      outputs: { element: [element], mu },
      readout: `μ = ${fmt(mu[1])}i ${sign} ${fmt(Math.abs(mu[0]))}; ${exact}`,
    };
  },
  /** The strip's edges and the isometric circles of a (at 0) and a⁻¹ (at μ). */
  overlay: ({ inputs }) => {
    const mu = inputs.mu;
    return [
      { shape: 'line', line: { a: [0, 0], b: [1, 0] } },
      { shape: 'line', line: { a: [0, mu[1]], b: [1, mu[1]] } },
      { shape: 'circle', circle: { c: [0, 0], r: 1 } },
      { shape: 'circle', circle: { c: mu, r: 1 } },
    ];
  },
  handles: ({ inputs }) => [{ handle: 'mu', at: inputs.mu }],
  drag: (_handle, to) => ({ mu: [...to] }),
});
