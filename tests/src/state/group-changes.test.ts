/** Editing inside groups: in-group changes, routed param patches, and the scoped store. */
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { groupNodes } from '../../../nodes/graph/grouping.ts';
import { registry } from '../../../nodes/types/index.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { scopeDocument } from '../../../src/state/group-changes.ts';
import { scopedStore } from '../../../src/state/scoped-store.ts';
import { createEditorStore } from '../../../src/state/store.ts';
import { doc, edge, node } from '../../nodes/support/doc.ts';

/** p → c → i → out with c and i grouped as g (p feeds the group's input "center"). */
const grouped = (): GraphDoc =>
  groupNodes(
    doc(
      [
        node('p', 'point'),
        node('c', 'circle', { radius: 0.5 }),
        node('i', 'inversion'),
        node('out', 'render'),
      ],
      [
        edge('e0', 'p.point', 'c.center'),
        edge('e1', 'c.circle', 'i.circle'),
        edge('e2', 'i.element', 'out.elements'),
      ],
    ),
    ['c', 'i'],
    'g',
  );
const inner = (d: GraphDoc) => d.nodes.find((n) => n.id === 'g')!.group!;

describe('changes inside groups', () => {
  it('in-group applies a change to the subgraph only', () => {
    const d = grouped();
    const next = applyChange(
      d,
      {
        type: 'in-group',
        path: ['g'],
        change: { type: 'set-params', patches: [{ nodeId: 'c', params: { radius: 2 } }] },
      },
      registry,
    );
    expect(inner(next).nodes[0].params.radius).toBe(2);
    expect(next.nodes.filter((n) => n.id !== 'g')).toEqual(d.nodes.filter((n) => n.id !== 'g'));
    const same = { type: 'in-group', path: ['nope'], change: { type: 'remove', nodeIds: ['c'] } } as const;
    expect(applyChange(d, same, registry)).toBe(d);
  });

  it('removing an inner node drops the ports it stood for and the outside wires to them', () => {
    const d = grouped();
    expect(inner(d).inputs.map((p) => p.name)).toEqual(['center']);
    const next = applyChange(
      d,
      { type: 'in-group', path: ['g'], change: { type: 'remove', nodeIds: ['c'] } },
      registry,
    );
    expect(inner(next).inputs).toEqual([]);
    expect(next.edges.some((e) => e.to.node === 'g')).toBe(false);
    expect(next.edges.some((e) => e.from.node === 'g')).toBe(true); // i's element is still exposed
  });

  it('a param patch naming a grouped node by its flattened id reaches it (a handle drag in the render)', () => {
    const next = applyChange(
      grouped(),
      { type: 'set-params', patches: [{ nodeId: 'c', params: { radius: 3 } }] },
      registry,
    );
    expect(inner(next).nodes[0].params.radius).toBe(3);
    const nowhere = { type: 'set-params', patches: [{ nodeId: 'zz', params: { radius: 3 } }] } as const;
    expect(applyChange(grouped(), nowhere, registry)).toEqual(grouped());
  });

  it('group and ungroup are changes (one undo step each)', () => {
    const d = grouped();
    const flat = applyChange(d, { type: 'ungroup', nodeId: 'g' }, registry);
    expect(flat.nodes.map((n) => n.id).sort()).toEqual(['c', 'i', 'out', 'p']);
    expect(applyChange(flat, { type: 'group', nodeIds: ['c', 'i'], groupId: 'g' }, registry)).toEqual(d);
  });
});

describe('the scoped store', () => {
  it('shows the group’s subgraph, wraps edits, keeps its own selection; undo is the document’s', () => {
    const base = createEditorStore(grouped(), registry);
    const store = scopedStore(base, ['g']);
    expect(store.getState().doc).toEqual(scopeDocument(base.getState().doc, ['g']));
    expect(store.getState().doc.nodes.map((n) => n.id)).toEqual(['c', 'i']);
    expect(store.getState()).toBe(store.getState()); // stable while nothing changes (React reads it)
    store.setSelection(['c']);
    expect(store.getState().selection).toEqual(new Set(['c']));
    expect(base.getState().selection.size).toBe(0);
    store.dispatch({ type: 'set-label', nodeId: 'c', label: 'C' });
    expect(inner(base.getState().doc).nodes[0].label).toBe('C');
    expect(store.getState().selection).toEqual(new Set(['c']));
    store.dispatch({ type: 'set-view', view: { center: [1, 1], scale: 3 } });
    expect(base.getState().doc.view.center).toEqual([1, 1]);
    store.undo();
    store.undo();
    expect(base.getState().doc).toEqual(grouped());
    expect(scopedStore(base, [])).toBe(base);
  });
});
