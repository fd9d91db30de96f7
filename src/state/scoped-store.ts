/**
 * The store as seen from inside an open group (docs/architecture.md "Groups"): its document is the
 * group's subgraph, every edit is wrapped in an `in-group` change on the real document (so undo,
 * autosave and the render see one document), and the selection is the group's own. View, meta and
 * whole-document loads pass through unchanged: they belong to the top level.
 */
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { Change } from './changes.ts';
import { scopeDocument } from './group-changes.ts';
import type { EditorState, EditorStore } from './store.ts';

const TOP_LEVEL: ReadonlySet<Change['type']> = new Set(['set-view', 'set-meta', 'load-document']);

export function scopedStore(base: EditorStore, path: readonly string[]): EditorStore {
  if (path.length === 0) return base;
  let selection: ReadonlySet<string> = new Set();
  const listeners = new Set<() => void>();
  let memo: { base: EditorState; selection: ReadonlySet<string>; state: EditorState } | null = null;
  let docMemo: { from: GraphDoc; doc: GraphDoc } | null = null;
  const scoped = (doc: GraphDoc): GraphDoc => {
    if (docMemo?.from !== doc)
      docMemo = { from: doc, doc: scopeDocument(doc, path) ?? { ...doc, nodes: [], edges: [] } };
    return docMemo.doc;
  };
  const wrap = (change: Change): Change =>
    TOP_LEVEL.has(change.type) ? change : { type: 'in-group', path, change };
  return {
    getState() {
      const b = base.getState();
      if (memo?.base !== b || memo.selection !== selection) {
        const doc = scoped(b.doc);
        const ids = new Set(doc.nodes.map((n) => n.id));
        const kept = [...selection].filter((id) => ids.has(id));
        if (kept.length !== selection.size) selection = new Set(kept);
        memo = { base: b, selection, state: { ...b, doc, selection } };
      }
      return memo.state;
    },
    subscribe(listener) {
      listeners.add(listener);
      const off = base.subscribe(listener);
      return () => {
        listeners.delete(listener);
        off();
      };
    },
    dispatch: (change, label) => base.dispatch(wrap(change), label),
    dispatchSilently: (change) => base.dispatchSilently(wrap(change)),
    preview: (change) => base.preview(wrap(change)),
    commit: (change, label) => base.commit(wrap(change), label),
    cancelGesture: () => base.cancelGesture(),
    undo: () => base.undo(),
    redo: () => base.redo(),
    setSelection(ids) {
      const next = new Set(ids);
      if (next.size === selection.size && [...next].every((id) => selection.has(id))) return;
      selection = next;
      for (const l of [...listeners]) l();
    },
    setTime: (time) => base.setTime(time),
    setPlaying: (playing) => base.setPlaying(playing),
  };
}
