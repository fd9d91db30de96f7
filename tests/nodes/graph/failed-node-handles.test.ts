import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';

describe('a failed node keeps the handles that need only its inputs', () => {
  it('collinear circle-3pt: error, no circle drawn, but its three points can still be dragged', () => {
    const ev = evaluateGraph(
      doc([node('c', 'circle-3pt', { a: [0, 0], b: [1, 0], c: [2, 0] }), node('out', 'render')]),
      registry,
    );
    expect(ev.nodes.get('c')?.diagnostics.some((d) => d.severity === 'error')).toBe(true);
    expect(ev.scene.overlays.filter((o) => o.nodeId === 'c')).toEqual([]);
    expect(ev.scene.handles.filter((h) => h.nodeId === 'c').map((h) => h.handle)).toEqual(['a', 'b', 'c']);
  });

  it('a circle with a failing radius offers no handle built from the missing output', () => {
    const ev = evaluateGraph(doc([node('k', 'circle', { radius: 0 })]), registry);
    expect(ev.nodes.get('k')?.outputs).toBeUndefined();
    expect(ev.scene.handles.filter((h) => h.nodeId === 'k')).toEqual([]);
  });
});
