import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import type { MobiusElement } from '../core/scene-elements.ts';
import { classifyTwoCircle, type MobiusClass, twoCircleRegions } from '../geometry/mobius.ts';
import { degrees, fail, fmt } from './shared.ts';

/** "elliptic, rotation 120°" / "hyperbolic (τ = 2.5)" — what the node shows. */
export function describeMobius(cls: MobiusClass): string {
  if (cls.type === 'elliptic' && cls.angle !== undefined) {
    return `elliptic: circles cross at ${degrees(cls.angle)}, rotation ${degrees(2 * cls.angle)}`;
  }
  return `${cls.type} (trace ${fmt(cls.trace)})`;
}

export const mobiusNode = defineNode({
  type: 'mobius',
  version: 1,
  label: 'Möbius (two circles)',
  category: 'Generators',
  color: '#e85d75',
  doc: 'The Möbius generator g = σ_C2∘σ_C1 and its inverse: hyperbolic, parabolic or elliptic by how the circles meet.',
  inputs: {
    c1: { type: 'circle', label: 'C1', default: { c: [0, 0], r: 1 } },
    c2: { type: 'circle', label: 'C2', default: { c: [0.3, 0], r: 2 } },
  },
  outputs: { element: { type: 'element', label: 'element' }, image: { type: 'circle', label: "C1'" } },
  params: {},
  evaluate: ({ inputs, nodeId }) => {
    const { c1, c2 } = inputs;
    if (!(c1.r > 0 && c2.r > 0)) return fail('both circles need a positive radius');
    const regions = twoCircleRegions(c1, c2);
    if (!regions.ok) return fail(regions.reason);
    const cls = classifyTwoCircle(c1, c2);
    const element: MobiusElement = { kind: 'mobius', nodeId, c1, c2, a: regions.a, b: regions.b };
    return {
      outputs: { element: [element], image: regions.c1Image },
      readout: describeMobius(cls),
      diagnostics: regions.tiling
        ? []
        : [
            diag(
              'notATiling',
              {},
              'the circles cross at an angle that is not π/n: the images overlap and do not tile',
            ),
          ],
    };
  },
  overlay: (_ctx, out) => [{ shape: 'circle', circle: out.image }],
});
