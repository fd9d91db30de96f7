/**
 * With hundreds of nodes, rebuilding every React Flow node on each selection, hover or drop is a
 * visible hitch: toFlowNodes keeps a node's identity while nothing it shows changed.
 */
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { diagnosticsByNode, type KfNode, toFlowNodes } from '../../../src/editor/flow-model.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { loadExample } from '../../support/examples.ts';

function flow(doc: GraphDoc, selection: string[], hovered: string | null, previous: KfNode[] = []) {
  const evaluation = evaluateGraph(doc, registry); // a fresh evaluation each time, as after any edit
  return toFlowNodes(
    doc,
    registry,
    evaluation.nodes,
    diagnosticsByNode(evaluation.diagnostics),
    new Set(selection),
    hovered,
    new Map(previous.map((n) => [n.id, n])),
  );
}

describe('React Flow nodes keep their identity while unchanged', () => {
  const { doc } = loadExample('four-disks-in-a-square');
  const first = flow(doc, [], null);

  it('a new evaluation of the same document, a selection or a hover rebuilds only the nodes concerned', () => {
    const again = flow(doc, ['A'], 'B', first);
    const rebuilt = again.filter((n, i) => n !== first[i]).map((n) => n.id);
    expect(rebuilt).toEqual(['A', 'B']);
    expect(again[0].selected).toBe(true);
    expect(again[1].data.hovered).toBe(true);
  });

  it('moving a point rebuilds the point and the nodes whose read-out changed, not the rest', () => {
    const moved = applyChange(
      doc,
      { type: 'set-params', patches: [{ nodeId: 'A', params: { x: -1.2 } }] },
      registry,
    );
    const after = flow(moved, [], null, first);
    const rebuilt = after.filter((n, i) => n !== first[i]).map((n) => n.id);
    expect(rebuilt).toContain('A');
    expect(rebuilt).not.toContain('c1');
    expect(rebuilt.length).toBeLessThan(doc.nodes.length / 2);
    for (const n of after) expect(n.data.node).toBe(moved.nodes.find((m) => m.id === n.id));
  });
});
