import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { add3, cross3, dot3, len3, normalize3, scale3, sub3 } from '../../../../nodes/geometry/space/vec3.ts';
import { point3, SEED } from './arbitraries.ts';

describe('vec3', () => {
  it('computes the basic operations', () => {
    expect(add3([1, 2, 3], [4, 5, 6])).toEqual([5, 7, 9]);
    expect(sub3([1, 2, 3], [4, 5, 6])).toEqual([-3, -3, -3]);
    expect(scale3([1, -2, 3], 2)).toEqual([2, -4, 6]);
    expect(dot3([1, 2, 3], [4, 5, 6])).toBe(32);
    expect(cross3([1, 0, 0], [0, 1, 0])).toEqual([0, 0, 1]);
    expect(len3([2, 3, 6])).toBe(7);
    expect(normalize3([0, 0, 0])).toEqual([0, 0, 0]);
    expect(normalize3([0, 0, 5])).toEqual([0, 0, 1]);
  });

  it('a × b is orthogonal to a and b, with |a × b|² = |a|²|b|² − (a·b)²', () => {
    fc.assert(
      fc.property(point3, point3, (a, b) => {
        const c = cross3(a, b);
        const s = Math.max(1, dot3(a, a) * dot3(b, b));
        expect(Math.abs(dot3(c, a))).toBeLessThan(1e-9 * s);
        expect(Math.abs(dot3(c, b))).toBeLessThan(1e-9 * s);
        expect(Math.abs(dot3(c, c) - (dot3(a, a) * dot3(b, b) - dot3(a, b) ** 2))).toBeLessThan(1e-9 * s);
      }),
      SEED,
    );
  });
});
