import { describe, expect, it } from 'vitest';
import type { MobiusMatrixElement } from '../../../nodes/core/scene.ts';
import type { Circle } from '../../../nodes/core/values.ts';
import { det } from '../../../nodes/geometry/mobius-matrix.ts';
import { fmtComplex } from '../../../nodes/types/mobius-matrix.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

describe('mobius-matrix node', () => {
  it('defaults: a hyperbolic map with disjoint isometric circles', () => {
    const r = checkDefaults('mobius-matrix');
    const [e] = r.outputs!.element as MobiusMatrixElement[];
    expect(det(e)[0]).toBeCloseTo(1, 12);
    expect(r.readout).toBe('hyperbolic, trace 2.5: scale ×4');
    expect((r.outputs!.isometric as Circle).c[0]).toBeCloseTo(-5 / 3, 12);
    expect((r.outputs!.isometricInverse as Circle).c[0]).toBeCloseTo(5 / 3, 12);
    expect(r.diagnostics).toEqual([]);
  });

  it('normalises any scalar multiple to det 1', () => {
    const r = evalNode('mobius-matrix', { a_re: 2.5, b_re: 1.5, c_re: 1.5, d_re: 2.5 }); // 2 × the default
    const [e] = r.outputs!.element as MobiusMatrixElement[];
    expect(e.a[0]).toBeCloseTo(1.25, 12);
    expect(e.c[0]).toBeCloseTo(0.75, 12);
  });

  it('det 0 and c = 0 are errors, the latter pointing to the affine nodes', () => {
    const singular = evalNode('mobius-matrix', { a_re: 1, b_re: 2, c_re: 2, d_re: 4 });
    expect(codes(singular)).toEqual(['KF303']);
    expect(singular.diagnostics[0].message).toMatch(/ad − bc = 0/);
    const affine = evalNode('mobius-matrix', { a_re: 2, b_re: 1, c_re: 0, d_re: 0.5 });
    expect(codes(affine)).toEqual(['KF303']);
    expect(affine.diagnostics[0].message).toMatch(/Translation strip or Spiral similarity/);
  });

  it('warns when the isometric circles overlap (elliptic of order > 2), not for an involution', () => {
    const elliptic = evalNode('mobius-matrix', { a_re: 0.5, b_re: -0.75, c_re: 1, d_re: 0.5 }); // τ = 1
    expect(codes(elliptic, 'warning')).toEqual(['KF304']);
    expect(elliptic.readout).toBe('elliptic, trace 1: rotation 120°');
    const involution = evalNode('mobius-matrix', { a_re: 0, b_re: -1, c_re: 1, d_re: 0 }); // z ↦ −1/z
    expect(codes(involution, 'warning')).toEqual([]);
  });

  it('shows loxodromic twist and formats complex traces', () => {
    const r = evalNode('mobius-matrix', { a_re: 1.5, a_im: 0.5, b_re: 0.5, c_re: 1, d_re: 1, d_im: 0.5 });
    expect(r.readout).toMatch(/^loxodromic, trace .*i: scale ×[\d.]+, turn -?[\d.]+°$/);
    expect(fmtComplex([1, -2])).toBe('1 − 2i');
    expect(fmtComplex([0, 1])).toBe('i');
    expect(fmtComplex([2.5, 0])).toBe('2.5');
  });
});
