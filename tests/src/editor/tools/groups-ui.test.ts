/** My groups (saved in the browser's storage) and the evaluation as one level of groups shows it. */
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { groupNodes } from '../../../../nodes/graph/grouping.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { compile } from '../../../../shader-gen/compile.ts';
import { groupSelection, ungroupSelection } from '../../../../src/editor/tools/group-actions.ts';
import {
  insertMyGroup,
  MY_GROUPS_KEY,
  readMyGroups,
  saveMyGroup,
} from '../../../../src/editor/tools/my-groups.ts';
import { scopeDiagnostics, scopeEvaluation } from '../../../../src/editor/tools/scope-evaluation.ts';
import { applyChange } from '../../../../src/state/changes.ts';
import { doc, edge, node } from '../../../nodes/support/doc.ts';

const memoryStorage = () => {
  const data = new Map<string, string>();
  return {
    getItem: (k: string) => data.get(k) ?? null,
    setItem: (k: string, v: string) => void data.set(k, v),
  };
};

/** A broken circle (radius −1) inside group g: its error shows on g at the top, on c inside. */
const grouped = (): GraphDoc =>
  groupNodes(
    doc(
      [node('c', 'circle', { radius: -1 }), node('i', 'inversion'), node('out', 'render')],
      [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
    ),
    ['c', 'i'],
    'g',
  );

describe('My groups', () => {
  it('saves, replaces by name, reads back valid entries only, and inserts a copy', () => {
    const storage = memoryStorage();
    const body = grouped().nodes[0].group!;
    saveMyGroup('Mirror', body, storage);
    saveMyGroup('Other', body, storage);
    saveMyGroup('Mirror', { ...body, outputs: [] }, storage);
    const list = readMyGroups(storage);
    expect(list.map((g) => g.name)).toEqual(['Mirror', 'Other']);
    expect(list[0].body.outputs).toEqual([]);
    storage.setItem(MY_GROUPS_KEY, JSON.stringify([{ name: 'bad', body: { nodes: 1 } }, list[1]]));
    expect(readMyGroups(storage).map((g) => g.name)).toEqual(['Other']);
    storage.setItem(MY_GROUPS_KEY, '{not json');
    expect(readMyGroups(storage)).toEqual([]);
    const d = grouped();
    const { change, nodeId } = insertMyGroup(d, list[1], { x: 10.4, y: 20 });
    const next = applyChange(d, change, registry);
    expect(next.nodes.find((n) => n.id === nodeId)).toMatchObject({ label: 'Other', position: [10, 20] });
    // Its inner ids clash with the first copy's: flattening keeps both apart, both draw.
    expect(evaluateGraph(next, registry).analysis.nodes.size).toBe(5);
  });

  it('Ctrl+G / Ctrl+Shift+G build one change each from the selection', () => {
    const d = doc([node('a', 'point'), node('b', 'point')]);
    const g = groupSelection(d, new Set(['a', 'b']))!;
    expect(g).toMatchObject({ type: 'group', nodeIds: ['a', 'b'], groupId: 'group1' });
    const after = applyChange(d, g, registry);
    expect(ungroupSelection(after, new Set(['a']))).toBeNull();
    expect(applyChange(after, ungroupSelection(after, new Set(['group1']))!, registry)).toEqual(d);
    expect(groupSelection(d, new Set())).toBeNull();
  });
});

describe('scopeDiagnostics', () => {
  it('a renderer diagnostic about a node inside a group shows on the group at the top, on the node inside', () => {
    // A circle beyond the GPU's float range inside g: the compiler's KF405 names the flattened node.
    const d = groupNodes(
      doc(
        [node('c', 'circle', { radius: 1e30 }), node('i', 'inversion'), node('out', 'render')],
        [edge('e1', 'c.circle', 'i.circle'), edge('e2', 'i.element', 'out.elements')],
      ),
      ['c', 'i'],
      'g',
    );
    const ev = evaluateGraph(d, registry);
    const fromRenderer = compile(ev.scene).diagnostics.filter((x) => x.code === 'KF405');
    expect(fromRenderer).toHaveLength(1);
    const flatId = fromRenderer[0].nodeId!;
    const top = scopeDiagnostics(fromRenderer, ev, [], d);
    expect(top).toMatchObject([{ code: 'KF405', nodeId: 'g' }]);
    // Named by title, never by id (an unlabelled node is unique at its level here).
    expect(top[0].message).toMatch(/^in group ‘Group’ → node ‘Circle inversion’: /);
    expect(scopeDiagnostics(fromRenderer, ev, ['g'], d)).toMatchObject([{ code: 'KF405', nodeId: flatId }]);
  });
});

describe('scopeEvaluation', () => {
  it('a problem inside a group shows on the group at the top and on its node inside', () => {
    const ev = evaluateGraph(grouped(), registry);
    const top = scopeEvaluation(ev, [], grouped());
    expect(top.diagnostics.some((d) => d.nodeId === 'g' && d.severity === 'error')).toBe(true);
    expect(top.nodes.has('c')).toBe(false);
    expect(top.nodes.has('out')).toBe(true);
    const inside = scopeEvaluation(ev, ['g'], grouped());
    expect(inside.diagnostics.some((d) => d.nodeId === 'c' && d.severity === 'error')).toBe(true);
    expect([...inside.nodes.keys()].sort()).toEqual(['c', 'i']);
    expect(inside.diagnostics.some((d) => d.nodeId === 'out')).toBe(false);
  });

  it('at the top the group’s badge says which inner node it is about; inside, the node’s own message', () => {
    const d = grouped();
    const labelled: GraphDoc = {
      ...d,
      nodes: d.nodes.map((n) =>
        n.group
          ? {
              ...n,
              label: 'Mirror pair',
              group: {
                ...n.group,
                nodes: n.group.nodes.map((m) => (m.id === 'c' ? { ...m, label: 'Circle 2' } : m)),
              },
            }
          : n,
      ),
    };
    const ev = evaluateGraph(labelled, registry);
    const own = ev.diagnostics.find((x) => x.nodeId === 'c' && x.severity === 'error')!;
    const top = scopeEvaluation(ev, [], labelled).diagnostics.filter((x) => x.nodeId === 'g');
    expect(top.map((x) => x.message)).toContain(`in group ‘Mirror pair’ → node ‘Circle 2’: ${own.message}`);
    expect(top.every((x) => x.port === undefined)).toBe(true); // g has no port of c's name
    const inside = scopeEvaluation(ev, ['g'], labelled).diagnostics.filter((x) => x.nodeId === 'c');
    expect(inside.map((x) => x.message)).toContain(own.message);
    expect(inside.some((x) => x.message.startsWith('in '))).toBe(false);
  });
});
