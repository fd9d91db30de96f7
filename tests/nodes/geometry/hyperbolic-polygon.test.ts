import { describe, expect, it } from 'vitest';
import type { Circle } from '../../../nodes/core/values.ts';
import { hyperbolicPolygonMirrors, isHyperbolicPolygon } from '../../../nodes/geometry/hyperbolic-polygon.ts';
import { intersectCircles } from '../../../nodes/geometry/intersect.ts';
import { dist, dot, len, scale, sub } from '../../../nodes/geometry/vec.ts';

/**
 * Interior angle of the region outside both circles at their crossing inside the unit disk: the
 * outward normals there are n_i = (V − c_i)/r_i and the region is {(x − V)·n1 > 0, (x − V)·n2 > 0},
 * a wedge of angle π − angle(n1, n2).
 */
function cornerAngle(k1: Circle, k2: Circle): number {
  const x = intersectCircles(k1, k2);
  if (!x.ok) throw new Error(x.reason);
  const V = x.points.find((p) => len(p) < 1)!;
  const n1 = scale(sub(V, k1.c), 1 / k1.r);
  const n2 = scale(sub(V, k2.c), 1 / k2.r);
  return Math.PI - Math.acos(dot(n1, n2));
}

const CASES = [
  [5, 3],
  [4, 3],
  [3, 4],
  [7, 2],
  [8, 5],
  [12, 2],
  [5, 10],
] as const;

describe('regular hyperbolic polygon {n, angle π/q}', () => {
  it('validity: (n − 2)(q − 1) > 2', () => {
    expect(isHyperbolicPolygon(4, 2)).toBe(false); // the Euclidean square
    expect(isHyperbolicPolygon(3, 3)).toBe(false); // the Euclidean equilateral triangle
    expect(isHyperbolicPolygon(3, 2)).toBe(false); // spherical
    expect(isHyperbolicPolygon(5, 2)).toBe(true);
    expect(isHyperbolicPolygon(3, 4)).toBe(true);
    expect(isHyperbolicPolygon(2, 9)).toBe(false);
  });

  for (const [n, q] of CASES) {
    it(`{${n}, π/${q}}: mirrors orthogonal to the unit circle, adjacent ones meeting at π/${q}`, () => {
      const mirrors = hyperbolicPolygonMirrors(n, q, 0.3);
      expect(mirrors).toHaveLength(n);
      for (let j = 0; j < n; j++) {
        const m = mirrors[j];
        expect(len(m.c) ** 2).toBeCloseTo(m.r * m.r + 1, 10); // orthogonal: |c|² = r² + 1
        expect(cornerAngle(m, mirrors[(j + 1) % n])).toBeCloseTo(Math.PI / q, 10);
        expect(dist(m.c, [0, 0]) - m.r).toBeGreaterThan(0); // the centre 0 is in the tile
      }
    });
  }
});
