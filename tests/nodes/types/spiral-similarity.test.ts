import { describe, expect, it } from 'vitest';
import type { SpiralSimilarityElement } from '../../../nodes/core/scene.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('spiral-similarity node', () => {
  it('defaults: scale 2.56 and turn 30° per step', () => {
    const r = checkDefaults('spiral-similarity');
    const [e] = r.outputs!.element as SpiralSimilarityElement[];
    expect(e).toMatchObject({ kind: 'spiral-similarity', r1: 0.5, r2: 0.8 });
    expect(e.angle).toBeCloseTo(Math.PI / 12, 12);
    expect(r.readout).toBe('each step: scale ×2.56, turn 30°');
  });

  it('needs 0 < r1 < r2', () => {
    expect(codes(evalNode('spiral-similarity', { r1: 0 }))).toEqual(['KF303']);
    expect(codes(evalNode('spiral-similarity', { r1: 1, r2: 1 }))).toEqual(['KF303']);
    expect(evalNode('spiral-similarity', { r1: 1, r2: 0.5 }).diagnostics[0].message).toMatch(
      /larger than r1/,
    );
  });

  it('draws the tile annulus; dragging the radii keeps r1 < r2', () => {
    const def = defOf('spiral-similarity');
    const r = evalNode('spiral-similarity', { r1: 1, r2: 2 });
    const circles = def.overlay!(r.ctx!, r.outputs!).filter((s) => s.shape === 'circle');
    expect(circles.map((s) => (s as { circle: { r: number } }).circle.r)).toEqual([1, 4]);
    expect(def.drag!('r1', [3, 0], r.ctx!).r1).toBeLessThan(2);
    expect(def.drag!('r2', [0.5, 0], r.ctx!).r2).toBeGreaterThan(1);
    expect(def.drag!('r2', [0, 3], r.ctx!)).toEqual({ r2: 3 });
    expect(def.drag!('center', [1, 1], r.ctx!)).toEqual({ center: [1, 1] });
  });
});
