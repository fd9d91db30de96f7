import { describe, expect, it } from 'vitest';
import { cosPiOver, sinPiOver } from '../../../nodes/geometry/angles.ts';
import { triangleMirrors } from '../../../nodes/geometry/triangle.ts';

describe('cos(π/k), sin(π/k)', () => {
  it('are exact where the value is rational (Math.cos(π/2) is 6e-17)', () => {
    expect([0, 1, 2, 3].map(cosPiOver)).toEqual([1, -1, 0, 0.5]);
    expect([0, 1, 2, 6].map(sinPiOver)).toEqual([0, 0, 1, 0.5]);
  });

  it('agree with Math.cos / Math.sin to the last bits for every order', () => {
    for (let k = 1; k <= 64; k++) {
      expect(cosPiOver(k)).toBeCloseTo(Math.cos(Math.PI / k), 15);
      expect(sinPiOver(k)).toBeCloseTo(Math.sin(Math.PI / k), 15);
    }
  });

  it('put the (2,3,7) group’s circle mirror exactly on the x-axis (docs/math.md check value)', () => {
    const m = triangleMirrors(7, 2, 3);
    if (m.mirror3.kind !== 'circle') throw new Error('expected a circle');
    expect(m.mirror3.c[1]).toBe(0);
    expect(m.mirror3.c[0]).toBeCloseTo(2.01219, 5);
    expect(m.mirror3.r).toBeCloseTo(1.74611, 5);
    expect(triangleMirrors(2, 3, 3).line2.n).toEqual([1, -0]);
  });
});
