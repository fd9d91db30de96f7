import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { type TriangleMirrors, triangleGeometry, triangleMirrors } from '../../../nodes/geometry/triangle.ts';
import { dot, len } from '../../../nodes/geometry/vec.ts';

/** The mirror-3 data as "inward normal at a point" and "intersection with a ray from 0". */
function mirror3Normal(m: TriangleMirrors, x: Vec2): Vec2 {
  if (m.mirror3.kind === 'line') return m.mirror3.n; // kept side (p−q)·n ≥ 0
  const { c, r } = m.mirror3; // kept side: outside the circle
  return [(x[0] - c[0]) / r, (x[1] - c[1]) / r];
}

/** Smallest t > 0 with t·dir on mirror 3 (the triangle's vertex on that ray). */
function hitMirror3(m: TriangleMirrors, dir: Vec2): Vec2 {
  let t: number;
  if (m.mirror3.kind === 'line') {
    const { q, n } = m.mirror3;
    t = dot(q, n) / dot(dir, n);
  } else {
    const { c, r } = m.mirror3; // |t dir − c|² = r²: t² − 2t(dir·c) + |c|² − r² = 0
    const b = dot(dir, c);
    const disc = Math.sqrt(b * b - (dot(c, c) - r * r));
    const roots = [b - disc, b + disc].filter((x) => x > 1e-12);
    t = Math.min(...roots);
  }
  return [t * dir[0], t * dir[1]];
}

/** Interior angle where two mirrors meet, from their inward (tile-side) unit normals: π − ∠(a, b). */
const interiorAngle = (a: Vec2, b: Vec2) => Math.PI - Math.acos(Math.max(-1, Math.min(1, dot(a, b))));

function checkAngles(p: number, q: number, r: number) {
  const m = triangleMirrors(p, q, r, 1.3);
  const a = Math.PI / p;
  // at 0: line 1 and line 2
  expect(interiorAngle(m.line1.n, m.line2.n)).toBeCloseTo(a, 12);
  // on the x-axis (line 1): π/q
  const v1 = hitMirror3(m, [1, 0]);
  expect(Math.abs(v1[1])).toBeLessThan(1e-12);
  expect(interiorAngle(m.line1.n, mirror3Normal(m, v1))).toBeCloseTo(Math.PI / q, 9);
  // on line 2: π/r
  const v2 = hitMirror3(m, [Math.cos(a), Math.sin(a)]);
  expect(dot(v2, m.line2.n)).toBeCloseTo(0, 12);
  expect(interiorAngle(m.line2.n, mirror3Normal(m, v2))).toBeCloseTo(Math.PI / r, 9);
}

describe('triangleGeometry', () => {
  it('classifies by 1/p + 1/q + 1/r against 1', () => {
    expect(triangleGeometry(7, 2, 3)).toBe('hyperbolic');
    expect(triangleGeometry(4, 3, 3)).toBe('hyperbolic');
    expect(triangleGeometry(5, 2, 3)).toBe('spherical');
    expect(triangleGeometry(4, 2, 3)).toBe('spherical');
    expect(triangleGeometry(2, 2, 9)).toBe('spherical');
    expect(triangleGeometry(6, 2, 3)).toBe('euclidean');
    expect(triangleGeometry(3, 3, 3)).toBe('euclidean');
    expect(triangleGeometry(4, 2, 4)).toBe('euclidean');
  });

  it('reads 0 as ∞ (an ideal vertex)', () => {
    expect(triangleGeometry(3, 0, 3)).toBe('hyperbolic');
    expect(triangleGeometry(2, 0, 2)).toBe('euclidean');
    expect(triangleGeometry(2, 3, 0)).toBe('hyperbolic');
    expect(triangleGeometry(3, 0, 0)).toBe('hyperbolic');
  });
});

describe('triangleMirrors', () => {
  it('(7, 2, 3): mirror 3 has centre ≈ (2.01219, 0) and radius ≈ 1.74611', () => {
    const m = triangleMirrors(7, 2, 3);
    expect(m.geometry).toBe('hyperbolic');
    if (m.mirror3.kind !== 'circle') throw new Error('expected a circle');
    expect(m.mirror3.c[0]).toBeCloseTo(2.01219, 5);
    expect(m.mirror3.c[1]).toBeCloseTo(0, 12);
    expect(m.mirror3.r).toBeCloseTo(1.74611, 5);
  });

  it('(4, 2, 3): mirror 3 has centre (1, 0) and radius √2', () => {
    const m = triangleMirrors(4, 2, 3);
    expect(m.geometry).toBe('spherical');
    if (m.mirror3.kind !== 'circle') throw new Error('expected a circle');
    expect(m.mirror3.c[0]).toBeCloseTo(1, 12);
    expect(m.mirror3.c[1]).toBeCloseTo(0, 12);
    expect(m.mirror3.r).toBeCloseTo(Math.SQRT2, 12);
  });

  it('lines 1 and 2 go through 0 as docs/math.md states', () => {
    const m = triangleMirrors(5, 2, 4);
    expect(m.line1).toEqual({ q: [0, 0], n: [0, 1] });
    expect(m.line2.n[0]).toBeCloseTo(Math.sin(Math.PI / 5), 15);
    expect(m.line2.n[1]).toBeCloseTo(-Math.cos(Math.PI / 5), 15);
  });

  it('hyperbolic mirror 3 is orthogonal to the unit circle; spherical passes through antipodes', () => {
    for (const [p, q, r] of [
      [7, 2, 3],
      [4, 3, 3],
      [5, 4, 2],
      [3, 0, 3],
      [8, 8, 8],
    ]) {
      const m = triangleMirrors(p, q, r);
      if (m.mirror3.kind !== 'circle') throw new Error('expected a circle');
      expect(dot(m.mirror3.c, m.mirror3.c)).toBeCloseTo(m.mirror3.r ** 2 + 1, 9); // |c|² = R² + 1
    }
    for (const [p, q, r] of [
      [4, 2, 3],
      [5, 2, 3],
      [3, 2, 3],
      [2, 2, 5],
    ]) {
      const m = triangleMirrors(p, q, r);
      if (m.mirror3.kind !== 'circle') throw new Error('expected a circle');
      expect(dot(m.mirror3.c, m.mirror3.c)).toBeCloseTo(m.mirror3.r ** 2 - 1, 9); // |c|² = R² − 1
    }
  });

  it('Euclidean mirror 3 is the line p·u = size with a unit normal, inside p·u > size', () => {
    const m = triangleMirrors(6, 2, 3, 2.5);
    expect(m.geometry).toBe('euclidean');
    if (m.mirror3.kind !== 'line') throw new Error('expected a line');
    expect(len(m.mirror3.n)).toBeCloseTo(1, 14);
    expect(-dot(m.mirror3.q, m.mirror3.n)).toBeCloseTo(2.5, 12); // distance of the line from 0
  });

  it.each([
    [7, 2, 3],
    [3, 3, 4],
    [5, 4, 2],
    [8, 3, 3],
    [4, 2, 3],
    [5, 2, 3],
    [3, 2, 3],
    [2, 2, 5],
    [6, 2, 3],
    [3, 3, 3],
    [4, 2, 4],
    [2, 3, 6],
    [2, 2, 2],
    [2, 3, 3],
    [2, 3, 5],
    [3, 3, 5],
  ])('(%i, %i, %i): the mirrors meet at angles π/p, π/q, π/r', (p, q, r) => {
    checkAngles(p, q, r);
  });

  it('an ideal vertex (q = ∞) makes mirror 3 tangent to line 1 on the unit circle', () => {
    const m = triangleMirrors(3, 0, 3);
    if (m.mirror3.kind !== 'circle') throw new Error('expected a circle');
    expect(m.mirror3.c[1]).toBeCloseTo(m.mirror3.r, 12); // tangent to y = 0
    expect(Math.abs(m.mirror3.c[0])).toBeCloseTo(1, 12); // at (±1, 0)
    // and r = ∞: tangent to line 2 at its unit point
    const m2 = triangleMirrors(4, 3, 0);
    if (m2.mirror3.kind !== 'circle') throw new Error('expected a circle');
    expect(Math.abs(dot(m2.mirror3.c, m2.line2.n))).toBeCloseTo(m2.mirror3.r, 12);
  });
});
