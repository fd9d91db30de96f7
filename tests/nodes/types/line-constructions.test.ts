import { describe, expect, it } from 'vitest';
import type { Line } from '../../../nodes/core/values.ts';
import { cross, dist, dot, sub } from '../../../nodes/geometry/vec.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

const dir = (l: Line) => sub(l.b, l.a);

describe('line constructions', () => {
  it('perpendicular bisector: every point on it is equally far from a and b', () => {
    checkDefaults('perpendicular-bisector');
    const a = [1, 2] as const;
    const b = [4, -1] as const;
    const l = evalNode('perpendicular-bisector', { a, b }).outputs!.line as Line;
    for (const t of [-2, 0, 0.5, 3]) {
      const p = [l.a[0] + t * (l.b[0] - l.a[0]), l.a[1] + t * (l.b[1] - l.a[1])] as const;
      expect(dist(p, a)).toBeCloseTo(dist(p, b), 12);
    }
    expect(codes(evalNode('perpendicular-bisector', { a: [1, 1], b: [1, 1] }))).toEqual(['KF303']);
  });

  it('parallel and perpendicular lines pass through the point', () => {
    const base = { a: [0, 0], b: [2, 1] };
    const par = checkDefaults('parallel-line');
    expect(par.outputs!.line).toBeDefined();
    const p = evalNode('parallel-line', { line: base, point: [3, 3] }).outputs!.line as Line;
    expect(p.a).toEqual([3, 3]);
    expect(cross(dir(p), [2, 1])).toBeCloseTo(0, 12);
    checkDefaults('perpendicular-line');
    const q = evalNode('perpendicular-line', { line: base, point: [3, 3] }).outputs!.line as Line;
    expect(q.a).toEqual([3, 3]);
    expect(dot(dir(q), [2, 1])).toBeCloseTo(0, 12);
    expect(codes(evalNode('parallel-line', { line: { a: [1, 1], b: [1, 1] } }))).toEqual(['KF303']);
  });
});
