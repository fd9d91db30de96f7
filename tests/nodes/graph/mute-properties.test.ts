/**
 * "Bypass = the graph without the node" (fast-check, fixed seed): muting a node whose wired outputs
 * are all element outputs gives exactly the Scene of the same document with that node and its
 * wires removed — every example, any such node.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { PORT_TYPE_INFO } from '../../../nodes/core/ports.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { loadDocument } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { exampleFiles } from '../../src/io/support/examples.ts';

const RUNS = { seed: 17, numRuns: 150 } as const;

const docs: GraphDoc[] = exampleFiles().map(({ name, text }) => {
  const r = loadDocument(JSON.parse(text), registry);
  if (!r.ok) throw new Error(`${name} does not load`);
  return r.doc;
});

/** Nodes with an element output whose every outgoing wire leaves from an element output. */
function elementNodes(doc: GraphDoc): string[] {
  return doc.nodes
    .filter((n) => {
      const def = registry.get(n.type);
      if (!def || !Object.values(def.outputs).some((o) => o.type === 'element')) return false;
      return doc.edges
        .filter((e) => e.from.node === n.id)
        .every((e) => def.outputs[e.from.port]?.type === 'element');
    })
    .map((n) => n.id);
}

const without = (doc: GraphDoc, id: string): GraphDoc => ({
  ...doc,
  nodes: doc.nodes.filter((n) => n.id !== id),
  edges: doc.edges.filter((e) => e.from.node !== id && e.to.node !== id),
});

const muting = (doc: GraphDoc, id: string): GraphDoc => ({
  ...doc,
  nodes: doc.nodes.map((n) => (n.id === id ? { ...n, muted: true } : n)),
});

describe('bypass = graph without the node', () => {
  it('holds for element nodes of every example', () => {
    const cases = docs.flatMap((doc) => elementNodes(doc).map((id) => ({ doc, id })));
    expect(cases.length).toBeGreaterThan(20);
    expect(PORT_TYPE_INFO.element.many).toBe(true); // why an empty list is "no elements"
    fc.assert(
      fc.property(
        fc.constantFrom(...cases),
        fc.double({ min: 0, max: 10, noNaN: true }),
        ({ doc, id }, time) => {
          const muted = evaluateGraph(muting(doc, id), registry, { time });
          const removed = evaluateGraph(without(doc, id), registry, { time });
          expect(muted.scene).toEqual(removed.scene);
          expect(muted.diagnostics.filter((d) => d.severity === 'error')).toEqual(
            removed.diagnostics.filter((d) => d.severity === 'error'),
          );
        },
      ),
      RUNS,
    );
  });

  it('and the muted scene differs from the unmuted one (the property is not vacuous)', () => {
    const changed = docs.filter((doc) =>
      elementNodes(doc).some(
        (id) =>
          JSON.stringify(evaluateGraph(muting(doc, id), registry).scene.elements) !==
          JSON.stringify(evaluateGraph(doc, registry).scene.elements),
      ),
    );
    expect(changed.length).toBeGreaterThan(10);
  });
});
