import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../../nodes/core/scene.ts';
import type { Line } from '../../../nodes/core/values.ts';
import { checkDefaults, codes, defOf, evalNode } from '../support/eval-node.ts';

for (const type of ['translation', 'parallel-mirrors', 'glide-reflection'] as const) {
  describe(`${type} node`, () => {
    it('defaults give one element: the strip −0.5 ≤ x < 0.5', () => {
      const r = checkDefaults(type);
      const [e] = r.outputs!.element as SceneElement[];
      expect(e).toMatchObject({ kind: type, q: [-0.5, 0], period: 1 });
      expect(r.readout).toBe('period 1 along 0°');
    });

    it('a zero or negative period is an error on the node', () => {
      expect(codes(evalNode(type, { period: 0 }))).toEqual(['KF303']);
      expect(codes(evalNode(type, { period: -1 }))).toContain('KF301'); // below the input's min
    });

    it('draws the strip edges (and the glide axis); dragging the far edge sets the period', () => {
      const def = defOf(type);
      const r = evalNode(type, { origin: [0, 0], angle: 90, period: 2 });
      const lines = def.overlay!(r.ctx!, r.outputs!).map((s) => (s as { line: Line }).line);
      expect(lines).toHaveLength(type === 'glide-reflection' ? 3 : 2);
      expect(lines[1].a[0]).toBeCloseTo(0, 12);
      expect(lines[1].a[1]).toBeCloseTo(2, 12); // far edge through origin + 2·(0, 1)
      const handles = def.handles!(r.ctx!, r.outputs!);
      expect(handles.map((h) => h.handle)).toEqual(['origin', 'edge', 'turn']);
      expect(def.drag!('edge', [5, 3.5], r.ctx!).period).toBeCloseTo(3.5, 12);
      expect(def.drag!('edge', [5, -3], r.ctx!).period).toBeGreaterThan(0); // never collapses
      expect(def.drag!('turn', [1, 0], r.ctx!)).toEqual({ angle: -90 });
      expect(def.drag!('origin', [1, 2], r.ctx!)).toEqual({ origin: [1, 2] });
    });
  });
}
