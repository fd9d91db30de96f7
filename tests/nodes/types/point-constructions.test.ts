import { describe, expect, it } from 'vitest';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('point constructions', () => {
  it('midpoint', () => {
    expect(checkDefaults('midpoint').outputs!.point).toEqual([0, 0]);
    expect(evalNode('midpoint', { a: [1, 2], b: [3, -2] }).outputs!.point).toEqual([2, 0]);
    const def = defOf('midpoint');
    const r = evalNode('midpoint');
    expect(def.handles!(r.ctx!, r.outputs!).map((h) => h.handle)).toEqual(['a', 'b']);
    expect(def.drag!('b', [4, 4], r.ctx!)).toEqual({ b: [4, 4] });
  });

  it('invert-point: image in the circle, the centre is an error', () => {
    checkDefaults('invert-point');
    const r = evalNode('invert-point', { circle: { c: [1, 0], r: 2 }, point: [2, 0] });
    expect(r.outputs!.point).toEqual([5, 0]); // 1 + 4/1
    expect(codes(evalNode('invert-point', { point: [0, 0] }))).toEqual(['KF303']);
  });

  it('reflect-point: mirror image in the line', () => {
    checkDefaults('reflect-point');
    const r = evalNode('reflect-point', { line: { a: [0, 0], b: [1, 1] }, point: [2, 0] });
    const p = r.outputs!.point as number[];
    expect(p[0]).toBeCloseTo(0, 12);
    expect(p[1]).toBeCloseTo(2, 12);
    expect(codes(evalNode('reflect-point', { line: { a: [1, 1], b: [1, 1] } }))).toEqual(['KF303']);
  });
});
