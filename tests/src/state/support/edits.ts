/**
 * Random editing sessions for the store's property tests: abstract edits (indices, not ids) made
 * concrete against the document they meet, so every generated sequence applies to any start
 * document. Some edits are deliberately invalid (a wire to a missing port, removing ids that do
 * not exist, adding a node whose id is taken): the store must refuse them cleanly.
 */
import { readFileSync } from 'node:fs';
import fc from 'fast-check';
import { emptyDocument, type GraphDoc } from '../../../../nodes/graph/document.ts';
import { parseDocumentText } from '../../../../nodes/graph/load.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { exampleNames, examplePath } from '../../../../src/cli/examples.ts';
import { newNode } from '../../../../src/editor/new-node.ts';
import { copyNodes, preparePaste } from '../../../../src/state/clipboard.ts';
import { idAllocator } from '../../../../src/state/ids.ts';
import type { EditorStore } from '../../../../src/state/store.ts';

/** Every example document, then the empty one: start documents are picked from this list. */
export const START_DOCS: readonly GraphDoc[] = [
  ...exampleNames().map((f) => {
    const loaded = parseDocumentText(readFileSync(examplePath(f), 'utf8'), registry);
    if (!loaded.ok) throw new Error(`${f} does not load`);
    return loaded.doc;
  }),
  emptyDocument('empty'),
];

const index = fc.nat({ max: 1_000 });
const picks = fc.array(index, { minLength: 1, maxLength: 4 });
/** Finite, never -0 (JSON has no -0, and no user types one). */
const value = fc.integer({ min: -4_000, max: 4_000 }).map((v) => v / 16);
const point = fc.tuple(value, value);

export type Edit =
  | { k: 'add'; type: number; at: [number, number]; takenId: boolean }
  | { k: 'remove'; nodes: number[]; missing: boolean }
  | { k: 'disconnect'; edge: number }
  | { k: 'connect'; from: number; out: number; to: number; in: number; broken: 'no' | 'node' | 'port' }
  | { k: 'param'; node: number; key: number; value: number }
  | { k: 'paste'; nodes: number[]; at: [number, number] }
  | { k: 'move'; nodes: number[]; by: [number, number] }
  | { k: 'label'; node: number; text: string }
  | { k: 'load'; doc: number }
  | { k: 'title'; text: string }
  /** Pan/zoom: a silent change, never an undo step. */
  | { k: 'pan'; center: [number, number]; scale: number }
  /** A drag: begin, many previews, then commit (or cancel). */
  | { k: 'gesture'; node: number; path: [number, number][]; cancel: boolean }
  | { k: 'select'; nodes: number[] }
  | { k: 'undo' }
  | { k: 'redo' };

export const editArb: fc.Arbitrary<Edit> = fc.oneof(
  fc.record({ k: fc.constant('add'), type: index, at: point, takenId: fc.boolean() }),
  fc.record({ k: fc.constant('remove'), nodes: picks, missing: fc.boolean() }),
  fc.record({ k: fc.constant('disconnect'), edge: index }),
  fc.record({
    k: fc.constant('connect'),
    from: index,
    out: index,
    to: index,
    in: index,
    broken: fc.constantFrom('no', 'no', 'node', 'port'),
  }),
  fc.record({ k: fc.constant('param'), node: index, key: index, value }),
  fc.record({ k: fc.constant('paste'), nodes: picks, at: point }),
  fc.record({ k: fc.constant('move'), nodes: picks, by: point }),
  fc.record({ k: fc.constant('label'), node: index, text: fc.constantFrom('', ' ', 'A', 'mirror', '  B ') }),
  fc.record({ k: fc.constant('load'), doc: index }),
  fc.record({ k: fc.constant('title'), text: fc.string({ maxLength: 12 }) }),
  fc.record({
    k: fc.constant('pan'),
    center: point,
    scale: fc.integer({ min: 1, max: 64 }).map((s) => s / 4),
  }),
  fc.record({
    k: fc.constant('gesture'),
    node: index,
    path: fc.array(point, { minLength: 1, maxLength: 12 }),
    cancel: fc.boolean(),
  }),
  fc.record({ k: fc.constant('select'), nodes: fc.array(index, { maxLength: 3 }) }),
  fc.constant({ k: 'undo' as const }),
  fc.constant({ k: 'redo' as const }),
);

export const sessionArb = fc.record({
  start: fc.nat({ max: START_DOCS.length - 1 }),
  edits: fc.array(editArb, { maxLength: 30 }),
});

const pick = <T>(list: readonly T[], i: number): T | undefined =>
  list.length === 0 ? undefined : list[i % list.length];
const pickIds = (doc: GraphDoc, is: readonly number[]) => [
  ...new Set(is.flatMap((i) => pick(doc.nodes, i)?.id ?? [])),
];

/** What one edit did to the store: whether it may leave an undo step, and whether it threw. */
export interface Applied {
  /** Kinds that must never add a history entry (selection, pan/zoom, a cancelled gesture). */
  readonly neverRecords: boolean;
  readonly threw: boolean;
}

/** Applies `edit` through the store's public API, the way the editor's UI calls it. */
export function applyEdit(store: EditorStore, edit: Edit): Applied {
  const doc = store.getState().doc;
  const done = (neverRecords = false, threw = false): Applied => ({ neverRecords, threw });
  switch (edit.k) {
    case 'add': {
      const def = registry.all[edit.type % registry.all.length];
      const node = newNode(doc, def, edit.at);
      const taken = edit.takenId ? pick(doc.nodes, edit.type)?.id : undefined;
      try {
        store.dispatch({ type: 'add-node', node: taken ? { ...node, id: taken } : node });
      } catch {
        return done(false, true);
      }
      return done();
    }
    case 'remove': {
      const ids = pickIds(doc, edit.nodes);
      store.dispatch({ type: 'remove', nodeIds: edit.missing ? ['no-such-node'] : ids }, 'delete');
      return done();
    }
    case 'disconnect': {
      const edge = pick(doc.edges, edit.edge);
      store.dispatch({ type: 'remove', nodeIds: [], edgeIds: [edge?.id ?? 'no-such-edge'] }, 'delete');
      return done();
    }
    case 'connect': {
      const from = pick(doc.nodes, edit.from);
      const to = pick(doc.nodes, edit.to);
      const outs = Object.keys(registry.get(from?.type ?? '')?.outputs ?? {});
      const ins = Object.keys(registry.get(to?.type ?? '')?.inputs ?? {});
      const fromPort = pick(outs, edit.out) ?? 'out';
      const toPort = edit.broken === 'port' ? 'no-such-port' : (pick(ins, edit.in) ?? 'in');
      const toNode = edit.broken === 'node' ? 'no-such-node' : (to?.id ?? 'no-such-node');
      store.dispatch({
        type: 'connect',
        edge: {
          id: idAllocator(doc)('e'),
          from: { node: from?.id ?? 'no-such-node', port: fromPort },
          to: { node: toNode, port: toPort },
        },
      });
      return done();
    }
    case 'param': {
      const node = pick(doc.nodes, edit.node);
      const def = node && registry.get(node.type);
      const key = pick(Object.keys({ ...def?.inputs, ...def?.params }), edit.key) ?? 'x';
      store.dispatch({
        type: 'set-params',
        patches: [{ nodeId: node?.id ?? 'no-such-node', params: { [key]: edit.value } }],
      });
      return done();
    }
    case 'paste': {
      const data = copyNodes(doc, pickIds(doc, edit.nodes));
      if (!data) return done(true); // nothing to copy: the UI does not paste
      store.dispatch({ type: 'paste', ...preparePaste(doc, data, edit.at) });
      return done();
    }
    case 'move': {
      const moves = pickIds(doc, edit.nodes).map((nodeId) => {
        const p = doc.nodes.find((n) => n.id === nodeId)!.position;
        return { nodeId, position: [p[0] + edit.by[0], p[1] + edit.by[1]] as [number, number] };
      });
      store.dispatch({ type: 'move-nodes', moves }, 'move nodes');
      return done();
    }
    case 'label':
      store.dispatch({
        type: 'set-label',
        nodeId: pick(doc.nodes, edit.node)?.id ?? 'none',
        label: edit.text,
      });
      return done();
    case 'load': {
      const next = START_DOCS[edit.doc % START_DOCS.length];
      store.dispatch({ type: 'load-document', doc: next }, 'open');
      return done();
    }
    case 'title':
      store.dispatch({ type: 'set-meta', meta: { ...doc.meta, title: edit.text } }, 'rename document');
      return done();
    case 'pan':
      store.dispatchSilently({ type: 'set-view', view: { center: edit.center, scale: edit.scale } });
      return done(true);
    case 'gesture': {
      const node = pick(doc.nodes, edit.node);
      if (!node) return done(true);
      const to = (p: [number, number]) => ({
        type: 'move-nodes' as const,
        moves: [
          {
            nodeId: node.id,
            position: [node.position[0] + p[0], node.position[1] + p[1]] as [number, number],
          },
        ],
      });
      for (const p of edit.path) store.preview(to(p));
      if (edit.cancel) {
        store.cancelGesture();
        return done(true);
      }
      store.commit(to(edit.path.at(-1)!), 'move nodes');
      return done();
    }
    case 'select':
      store.setSelection(pickIds(doc, edit.nodes));
      return done(true);
    case 'undo':
      store.undo();
      return done();
    case 'redo':
      store.redo();
      return done();
  }
}
