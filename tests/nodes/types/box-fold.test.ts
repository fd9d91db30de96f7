/** The box-fold node: its element, its read-out and its refusals (docs/math-3d.md §10). */
import { describe, expect, it } from 'vitest';
import type { NodeElement3d } from '../../../nodes/core/scene-3d.ts';
import { stepElement3d } from '../../../nodes/geometry/space/iis-3d.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';

const alone = (params: Record<string, unknown> = {}) => {
  const result = evaluateGraph(doc([node('n', 'box-fold', params)]), registry).nodes.get('n')!;
  return {
    ...result,
    element: (result.outputs?.element as NodeElement3d[] | undefined)?.[0],
    messages: result.diagnostics.map((d) => `${d.code} ${d.message}`),
  };
};

describe('box-fold', () => {
  it('makes one box-fold element that folds the outside of the box into it', () => {
    const r = alone({ center: [1, 0, 0], halfSize: [1, 1, 0.5] });
    expect(r.element).toEqual({
      kind: 'box-fold',
      nodeId: 'n',
      box: { center: [1, 0, 0], halfSize: [1, 1, 0.5] },
    });
    expect(r.readout).toBe('lattice period (4, 4, 2)');
    expect(stepElement3d(r.element!, [1, 0, 0.4])).toBeNull();
    expect(stepElement3d(r.element!, [1, 0, 0.75])).toEqual({ x: [1, 0, 0.25], factor: 1 });
  });

  it('refuses a half size that is not positive', () => {
    expect(alone({ halfSize: [1, 0, 1] }).messages).toEqual([
      'KF303 the box needs a positive half size along x, y and z, got (1, 0, 1)',
    ]);
  });
});
