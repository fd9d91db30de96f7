/**
 * Groups (fast-check, fixed seed), on every example with any set of its nodes grouped:
 * - ungroup(group(doc)) is the document again, up to node and edge order and the ids of wires
 *   into the group (one outside output feeding several inner inputs is one group input: its extra
 *   wires come back with fresh ids);
 * - evaluating the grouped document (flattened) gives exactly the Scene of the flat one;
 * - groups of groups too;
 * - frames: one whose nodes are all grouped goes inside the group, the others stay, and ungrouping
 *   puts every frame back where it was (moved with the nodes when the group node was moved).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { flattenGroups } from '../../../nodes/graph/flatten.ts';
import { nodesInFrame } from '../../../nodes/graph/frames.ts';
import { groupNodes, ungroupNode } from '../../../nodes/graph/grouping.ts';
import { loadDocument } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { frameAround } from '../../../src/editor/tools/frames.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { idAllocator } from '../../../src/state/ids.ts';
import { exampleFiles } from '../../src/io/support/examples.ts';

const RUNS = { seed: 23, numRuns: 120 } as const;

const docs: GraphDoc[] = exampleFiles().map(({ name, text }) => {
  const r = loadDocument(JSON.parse(text), registry);
  if (!r.ok) throw new Error(`${name} does not load`);
  return r.doc;
});

/** A document compared up to order: nodes by id; edges by their ends (ids kept where they were). */
function normal(doc: GraphDoc) {
  const ends = (e: GraphDoc['edges'][number]) => JSON.stringify([e.from, e.to]);
  return {
    ...doc,
    nodes: [...doc.nodes].sort((a, b) => (a.id < b.id ? -1 : 1)),
    edges: doc.edges.map(ends).sort(),
    ...(doc.frames ? { frames: [...doc.frames].sort((a, b) => (a.id < b.id ? -1 : 1)) } : {}),
  };
}

/** `doc` with a frame around each of these sets of nodes, made as the Frame button makes them. */
function framed(doc: GraphDoc, sets: readonly (readonly string[])[]): GraphDoc {
  return sets.reduce((d, ids) => applyChange(d, frameAround(d, new Set(ids))!, registry), doc);
}

const caseArb = fc.constantFrom(...docs).chain((doc) =>
  fc.tuple(
    fc.constant(doc),
    fc.subarray(
      doc.nodes.map((n) => n.id),
      { minLength: 1 },
    ),
  ),
);

/** A document with up to three frames, and the nodes to group. */
const framedArb = fc.constantFrom(...docs).chain((doc) => {
  const ids = doc.nodes.map((n) => n.id);
  return fc
    .tuple(fc.array(fc.subarray(ids, { minLength: 1 }), { maxLength: 3 }), fc.subarray(ids, { minLength: 1 }))
    .map(([sets, chosen]) => [framed(doc, sets), chosen] as const);
});

const group = (doc: GraphDoc, ids: readonly string[]) => groupNodes(doc, ids, idAllocator(doc)('group'));
const ungroup = (doc: GraphDoc, id: string) => ungroupNode(doc, id, idAllocator(doc));

describe('group → ungroup', () => {
  it('restores the document (nodes exactly, every wire, every kept edge id)', () => {
    fc.assert(
      fc.property(caseArb, ([doc, ids]) => {
        const grouped = group(doc, ids);
        const g = grouped.nodes.find((n) => n.group)!;
        expect(grouped.nodes).toHaveLength(doc.nodes.length - ids.length + 1);
        const back = ungroup(grouped, g.id);
        expect(normal(back)).toEqual(normal(doc));
        expect(new Set(back.edges.map((e) => e.id)).size).toBe(back.edges.length);
        // Every wire that did not enter the group comes back exactly, id included; a wire that
        // entered may come back with a fresh id (one outside output feeding several inner inputs).
        const chosen = new Set(ids);
        for (const e of doc.edges.filter((e) => !(chosen.has(e.to.node) && !chosen.has(e.from.node))))
          expect(back.edges.find((x) => x.id === e.id)).toEqual(e);
      }),
      RUNS,
    );
  });

  it('frames: those whose nodes are all grouped go inside, the rest stay; ungroup puts them all back', () => {
    fc.assert(
      fc.property(framedArb, fc.integer({ min: -300, max: 300 }), ([doc, ids], shift) => {
        const grouped = group(doc, ids);
        const g = grouped.nodes.find((n) => n.group)!;
        const chosen = new Set(ids);
        const inside = (doc.frames ?? []).filter((f) => {
          const carried = nodesInFrame(doc.nodes, f);
          return carried.length > 0 && carried.every((id) => chosen.has(id));
        });
        expect(g.group!.frames ?? []).toEqual(inside);
        expect((grouped.frames?.length ?? 0) + inside.length).toBe(doc.frames?.length ?? 0);
        expect(normal(ungroup(grouped, g.id))).toEqual(normal(doc));
        // Moved first: the frames that went inside come back moved with their nodes.
        const moved = {
          ...grouped,
          nodes: grouped.nodes.map((n) =>
            n.id === g.id
              ? { ...n, position: [n.position[0] + shift, n.position[1]] as [number, number] }
              : n,
          ),
        };
        const back = ungroup(moved, g.id);
        for (const f of inside)
          expect(back.frames?.find((x) => x.id === f.id)?.position).toEqual([
            f.position[0] + shift,
            f.position[1],
          ]);
      }),
      RUNS,
    );
  });

  it('evaluates to the same Scene as the flat graph, at any time', () => {
    fc.assert(
      fc.property(caseArb, fc.double({ min: 0, max: 10, noNaN: true }), ([doc, ids], time) => {
        const grouped = group(doc, ids);
        expect(evaluateGraph(grouped, registry, { time }).scene).toEqual(
          evaluateGraph(doc, registry, { time }).scene,
        );
      }),
      RUNS,
    );
  });

  it('nests: a group inside a group flattens and ungroups level by level', () => {
    fc.assert(
      fc.property(caseArb, ([doc, ids]) => {
        const once = group(doc, ids);
        const inner = once.nodes.find((n) => n.group)!;
        const rest = once.nodes.filter((n) => n.id !== inner.id).map((n) => n.id);
        const twice = group(once, [inner.id, ...rest.slice(0, 2)]);
        const outer = twice.nodes.find((n) => n.group)!;
        expect(
          flattenGroups(twice)
            .doc.nodes.map((n) => n.id)
            .sort(),
        ).toEqual(doc.nodes.map((n) => n.id).sort());
        expect(evaluateGraph(twice, registry).scene).toEqual(evaluateGraph(doc, registry).scene);
        const back = ungroup(ungroup(twice, outer.id), inner.id);
        expect(normal(back)).toEqual(normal(doc));
      }),
      { ...RUNS, numRuns: 60 },
    );
  });
});
