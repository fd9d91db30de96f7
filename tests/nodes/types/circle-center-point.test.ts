import { describe, expect, it } from 'vitest';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('circle-center-point node', () => {
  it('radius = distance from the centre to the point; coincident points are an error', () => {
    expect(checkDefaults('circle-center-point').outputs!.circle).toEqual({ c: [0, 0], r: 1 });
    expect(evalNode('circle-center-point', { center: [1, 1], through: [4, 5] }).outputs!.circle).toEqual({
      c: [1, 1],
      r: 5,
    });
    expect(codes(evalNode('circle-center-point', { center: [2, 2], through: [2, 2] }))).toEqual(['KF303']);
  });

  it('both points are draggable', () => {
    const def = defOf('circle-center-point');
    const r = evalNode('circle-center-point');
    expect(def.handles!(r.ctx!, r.outputs!).map((h) => h.handle)).toEqual(['center', 'through']);
  });
});
