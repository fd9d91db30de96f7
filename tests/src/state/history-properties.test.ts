/**
 * History under random editing sessions (fast-check, fixed seed): every edit goes through the
 * store's real API, from an example or an empty document. A reference model (the list of
 * documents the history should hold, and where we are in it) is checked after every edit:
 * an edit that changes the document is exactly one undo step and clears redo, one that changes
 * nothing (an invalid edit) is no step and leaves the document as it was, selection and pan/zoom
 * are never steps, a gesture is one step, and undo/redo walk the model's documents exactly.
 */
import { isDeepStrictEqual } from 'node:util';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { registry } from '../../../nodes/types/index.ts';
import { createEditorStore, type EditorStore } from '../../../src/state/store.ts';
import { applyEdit, type Edit, START_DOCS, sessionArb } from './support/edits.ts';

const RUNS = { seed: 42, numRuns: 200 } as const;

/** The document without its view (pan/zoom is not history, so it may differ after a silent pan). */
const withoutView = ({ view: _view, ...rest }: GraphDoc) => rest;

/** Walks the session, checking the store against the model after each edit; returns the model. */
function replay(store: EditorStore, edits: readonly Edit[]) {
  const timeline: GraphDoc[] = [store.getState().doc];
  let pos = 0;
  let panned = false;
  const same = (a: GraphDoc, b: GraphDoc) =>
    panned ? expect(withoutView(a)).toStrictEqual(withoutView(b)) : expect(a).toStrictEqual(b);

  for (const edit of edits) {
    const before = store.getState();
    if (edit.k === 'undo' || edit.k === 'redo') {
      const target = edit.k === 'undo' ? pos - 1 : pos + 1;
      store[edit.k]();
      if (target >= 0 && target < timeline.length) {
        pos = target;
        same(store.getState().doc, timeline[pos]);
      } else {
        expect(store.getState().doc).toBe(before.doc);
        expect(store.getState().history).toBe(before.history);
      }
    } else {
      const applied = applyEdit(store, edit);
      const after = store.getState();
      if (edit.k === 'pan') panned = true;
      if (applied.threw || applied.neverRecords) {
        expect(after.history).toBe(before.history);
        if (edit.k !== 'pan') expect(after.doc).toBe(before.doc);
      } else if (isDeepStrictEqual(after.doc, before.doc)) {
        // Nothing visible changed (e.g. a wire to a missing port): no undo step, the same document.
        expect(after.history).toBe(before.history);
        expect(after.doc).toBe(before.doc);
      } else {
        expect(after.history.past).toHaveLength(before.history.past.length + 1);
        expect(after.history.future).toHaveLength(0);
        timeline.splice(pos + 1, timeline.length, after.doc);
        pos++;
      }
    }
    const { history, gestureBase } = store.getState();
    expect(gestureBase).toBeNull();
    expect(history.past).toHaveLength(pos);
    expect(history.future).toHaveLength(timeline.length - 1 - pos);
  }
  return { timeline, pos, same };
}

describe('history properties', () => {
  it('undo and redo walk exactly the documents the edits made; a new edit clears redo', () => {
    fc.assert(
      fc.property(sessionArb, ({ start, edits }) => {
        const store = createEditorStore(START_DOCS[start], registry);
        const { timeline, pos, same } = replay(store, edits);
        for (let i = 0; i < pos + 2; i++) store.undo();
        same(store.getState().doc, timeline[0]);
        expect(store.getState().history.past).toHaveLength(0);
        for (let i = 0; i < timeline.length + 2; i++) store.redo();
        same(store.getState().doc, timeline.at(-1)!);
        expect(store.getState().history.future).toHaveLength(0);
      }),
      RUNS,
    );
  });

  it('without pan/zoom, undoing everything restores the first document EXACTLY, view included', () => {
    const plain = (e: Edit) => e.k !== 'pan' && e.k !== 'undo' && e.k !== 'redo';
    fc.assert(
      fc.property(sessionArb, ({ start, edits }) => {
        const initial = START_DOCS[start];
        const store = createEditorStore(initial, registry);
        for (const edit of edits) if (plain(edit)) applyEdit(store, edit);
        const final = store.getState().doc;
        while (store.getState().history.past.length > 0) store.undo();
        expect(store.getState().doc).toStrictEqual(initial);
        while (store.getState().history.future.length > 0) store.redo();
        expect(store.getState().doc).toStrictEqual(final);
      }),
      RUNS,
    );
  });

  it('a selection change never touches the document or the history', () => {
    fc.assert(
      fc.property(sessionArb, fc.array(fc.nat(), { maxLength: 5 }), ({ start, edits }, ids) => {
        const store = createEditorStore(START_DOCS[start], registry);
        for (const edit of edits) applyEdit(store, edit);
        const { doc, history } = store.getState();
        store.setSelection(ids.map((i) => doc.nodes[i % Math.max(1, doc.nodes.length)]?.id ?? 'x'));
        store.setSelection([]);
        expect(store.getState().doc).toBe(doc);
        expect(store.getState().history).toBe(history);
      }),
      RUNS,
    );
  });

  it('a continuous gesture (begin, many previews, commit) is ONE undo step back to where it began', () => {
    const moveArb = fc.array(
      fc.tuple(fc.integer({ min: -300, max: 300 }), fc.integer({ min: -300, max: 300 })),
      { minLength: 2, maxLength: 40 },
    );
    fc.assert(
      fc.property(sessionArb, fc.nat(), moveArb, ({ start, edits }, which, path) => {
        const store = createEditorStore(START_DOCS[start], registry);
        for (const edit of edits) applyEdit(store, edit);
        const { doc: began, history } = store.getState();
        const node = began.nodes[which % Math.max(1, began.nodes.length)];
        if (!node || path.every(([x, y]) => x === 0 && y === 0)) return;
        const last = path.findLast(([x, y]) => x !== 0 || y !== 0)!;
        path.push(last);
        const move = ([dx, dy]: [number, number]) => ({
          type: 'set-params' as const,
          patches: [{ nodeId: node.id, params: { kfGestureProbe: dx * 1000 + dy } }],
        });
        for (const p of path) {
          store.preview(move(p));
          expect(store.getState().history).toBe(history); // previews are never steps
        }
        store.commit(move(last));
        expect(store.getState().history.past).toHaveLength(Math.min(history.past.length + 1, 200));
        store.undo();
        expect(store.getState().doc).toStrictEqual(began);
      }),
      RUNS,
    );
  });
});
