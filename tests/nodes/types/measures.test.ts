import { describe, expect, it } from 'vitest';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

describe('measure nodes', () => {
  it('angle at the vertex, radians out, degrees shown', () => {
    const r = checkDefaults('angle');
    expect(r.outputs!.angle).toBeCloseTo(Math.PI / 2, 14);
    expect(r.readout).toBe('90°');
    expect(r.outputs!.degrees).toBeCloseTo(90, 12);
    const obtuse = evalNode('angle', { a: [1, 0], b: [0, 0], c: [-1, 1] });
    expect(obtuse.outputs!.angle).toBeCloseTo((3 * Math.PI) / 4, 14);
    const straight = evalNode('angle', { a: [1, 0], b: [0, 0], c: [-1, 0] });
    expect(straight.outputs!.angle).toBeCloseTo(Math.PI, 14);
    expect(codes(evalNode('angle', { a: [0, 0] }))).toEqual(['KF303']);
  });

  it('distance', () => {
    expect(checkDefaults('distance').outputs!.distance).toBe(1);
    const r = evalNode('distance', { a: [1, 1], b: [4, 5] });
    expect(r.outputs!.distance).toBe(5);
    expect(r.readout).toBe('5');
  });
});
