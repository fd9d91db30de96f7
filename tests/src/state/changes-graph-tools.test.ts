/** The graph tools' changes: mute, frames, reroute points — each a pure step, a no-op returns the doc itself. */
import { describe, expect, it } from 'vitest';
import type { GraphFrame } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { doc, edge, node } from '../../nodes/support/doc.ts';

const base = () =>
  doc(
    [node('c', 'circle'), node('i', 'inversion'), node('out', 'render')],
    [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
  );
const frame: GraphFrame = { id: 'f1', title: 'Mirrors', color: '#335577', position: [0, 0], size: [100, 80] };

describe('graph tool changes', () => {
  it('set-muted marks nodes muted and unmuting removes the key (the document is as before)', () => {
    const d = base();
    const m = applyChange(d, { type: 'set-muted', nodeIds: ['i', 'c'], muted: true }, registry);
    expect(m.nodes.map((n) => n.muted)).toEqual([true, true, undefined]);
    expect(applyChange(m, { type: 'set-muted', nodeIds: ['i'], muted: true }, registry)).toBe(m);
    const back = applyChange(m, { type: 'set-muted', nodeIds: ['i', 'c'], muted: false }, registry);
    expect(back).toEqual(d);
    expect('muted' in back.nodes[0]).toBe(false);
  });

  it('put-frame adds or replaces by id; remove-frames drops the key when none is left', () => {
    const d = base();
    const a = applyChange(d, { type: 'put-frame', frame }, registry);
    expect(a.frames).toEqual([frame]);
    expect(applyChange(a, { type: 'put-frame', frame: { ...frame } }, registry)).toBe(a);
    const b = applyChange(a, { type: 'put-frame', frame: { ...frame, title: 'T' } }, registry);
    expect(b.frames).toEqual([{ ...frame, title: 'T' }]);
    expect(applyChange(b, { type: 'remove-frames', frameIds: ['nope'] }, registry)).toBe(b);
    expect(applyChange(b, { type: 'remove-frames', frameIds: ['f1'] }, registry)).toEqual(d);
  });

  it('set-via sets and clears an edge’s reroute points', () => {
    const d = base();
    const a = applyChange(d, { type: 'set-via', edgeId: 'e1', via: [[5, 6]] }, registry);
    expect(a.edges[0].via).toEqual([[5, 6]]);
    expect(applyChange(a, { type: 'set-via', edgeId: 'e1', via: [[5, 6]] }, registry)).toBe(a);
    expect(applyChange(a, { type: 'set-via', edgeId: 'e1', via: [] }, registry)).toEqual(d);
  });
});
