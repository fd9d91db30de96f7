import { describe, expect, it } from 'vitest';
import type { RotationElement } from '../../../nodes/core/scene.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

describe('rotation node', () => {
  it('defaults: order 6 about the origin, wedge from +x', () => {
    const r = checkDefaults('rotation');
    const [e] = r.outputs!.element as RotationElement[];
    expect(e).toMatchObject({ kind: 'rotation', c: [0, 0], b1: [1, 0], order: 6 });
    expect(r.readout).toBe('order 6: wedge of 60°');
  });

  it('rejects order 1 and fractional orders', () => {
    expect(codes(evalNode('rotation', { order: 1 }))).toContain('KF301');
    expect(codes(evalNode('rotation', { order: 2.5 }))).toContain('KF301');
  });

  it('draws the wedge rays; dragging moves the centre and turns the start ray', () => {
    const def = defOf('rotation');
    const r = evalNode('rotation', { center: [1, 1], order: 4, angle: 0 });
    const shapes = def.overlay!(r.ctx!, r.outputs!);
    expect(shapes.map((s) => s.shape)).toEqual(['point', 'line', 'line']);
    const second = shapes[2] as unknown as { line: { a: number[]; b: number[] } };
    expect(second.line.b[0]).toBeCloseTo(1, 12); // the ray at 90°
    expect(second.line.b[1]).toBeCloseTo(2, 12);
    expect(def.drag!('direction', [1, 3], r.ctx!)).toEqual({ angle: 90 });
    expect(def.drag!('center', [0, 0], r.ctx!)).toEqual({ center: [0, 0] });
  });
});
