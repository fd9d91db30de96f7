import { describe, expect, it } from 'vitest';
import type { IisState } from '../../../shader-gen/elements/element-kind.ts';
import { maskitSlice } from '../../../shader-gen/elements/maskit-slice.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('maskit-slice node', () => {
  it('defaults: μ = 0.2 + 1.95i, in the slice, cusps up to q = 24; μ is an output too', () => {
    const r = checkDefaults('maskit-slice');
    expect(r.outputs!.element).toEqual([{ kind: 'maskit-slice', nodeId: 'n', maxDenominator: 24 }]);
    expect(r.outputs!.mu).toEqual([0.2, 1.95]);
    expect(r.readout).toBe('μ = 0.2 + 1.95i: in the slice (discrete, free)');
  });

  it('says when μ is below the boundary (KF325), e.g. at the real axis or under the 1/2 cusp', () => {
    const notes = (mu: number[]) => evalNode('maskit-slice', { mu }).diagnostics.map((d) => d.code);
    expect(notes([0.5, 0.5])).toEqual(['KF325']);
    expect(notes([1, 1.7])).toEqual(['KF325']);
    expect(notes([1, 1.8])).toEqual([]);
    expect(codes(evalNode('maskit-slice', { mu: [1, 1.7] }))).toEqual([]); // a note, not an error
    expect(evalNode('maskit-slice', { mu: [1, 1.7] }).readout).toMatch(/outside the slice/);
  });

  it('offers μ as a handle placed by a click, and a drag moves it', () => {
    const def = defOf('maskit-slice');
    const r = evalNode('maskit-slice', { mu: [0.3, 2.1] });
    expect(def.handles!(r.ctx!, r.outputs!)).toEqual([{ handle: 'mu', at: [0.3, 2.1], placeOnClick: true }]);
    expect(def.drag!('mu', [-0.4, 1.9], r.ctx!)).toEqual({ mu: [-0.4, 1.9] });
  });
});

describe('maskit-slice element', () => {
  const e = { kind: 'maskit-slice', nodeId: 'n', maxDenominator: 24 } as const;

  it('μ in the slice is in the tile at depth 0; below it the run never escapes', () => {
    expect(interpret({ elements: [e], maxIterations: 50 }, [-1, 2.2])).toMatchObject({
      escaped: true,
      depth: 0,
      final: [-1, 2.2],
    });
    const below = interpret({ elements: [e], maxIterations: 50 }, [-1, 1.5]);
    expect(below.escaped).toBe(false);
    expect(below.final).toEqual([-1, 1.5]);
  });

  it('its step leaves the point and the scale alone and ends any run', () => {
    const st: IisState = { x: 0.5, y: 1, s: 1, depth: 3 };
    expect(maskitSlice.cpu.step(e, st)).toBe(true);
    expect(st).toMatchObject({ x: 0.5, y: 1, s: 1 });
    expect(st.depth).toBeGreaterThanOrEqual(10_000);
    const above: IisState = { x: 0.5, y: 2.5, s: 1, depth: 0 };
    expect(maskitSlice.cpu.step(e, above)).toBe(false);
    expect(above).toEqual({ x: 0.5, y: 2.5, s: 1, depth: 0 });
  });
});
