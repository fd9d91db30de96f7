/**
 * The editor's store: the GraphDoc (single source of truth), its history, the gesture in progress,
 * the selection (never in the document, never in history) and animation time. Framework-free;
 * React reads it through use-store.ts.
 */
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { applyChange, type Change } from './changes.ts';
import { emptyHistory, type History, record, redo, undo } from './history.ts';

export interface EditorState {
  readonly doc: GraphDoc;
  readonly history: History;
  /** The document when the current gesture began (null when no gesture is in progress). */
  readonly gestureBase: GraphDoc | null;
  readonly selection: ReadonlySet<string>;
  /** Animation time in seconds, and whether it runs. */
  readonly time: number;
  readonly playing: boolean;
}

export interface EditorStore {
  getState(): EditorState;
  subscribe(listener: () => void): () => void;
  /** One edit = one undo step. */
  dispatch(change: Change, label?: string): void;
  /** A change that is not an undo step (e.g. the view after pan/zoom). */
  dispatchSilently(change: Change): void;
  /**
   * Live preview of a continuous gesture: `change` is applied to the document as it was when the
   * gesture began (so it must be absolute, e.g. the param's current value), no history entry.
   */
  preview(change: Change): void;
  /** Ends a gesture with its final change: ONE undo step from the gesture's start. */
  commit(change: Change, label?: string): void;
  /** Abandons a gesture, restoring the document it began with. */
  cancelGesture(): void;
  undo(): void;
  redo(): void;
  setSelection(ids: Iterable<string>): void;
  setTime(time: number): void;
  setPlaying(playing: boolean): void;
}

const describe = (change: Change): string =>
  change.type === 'in-group' ? describe(change.change) : change.type.replace('-', ' ');

export function createEditorStore(initial: GraphDoc, registry: NodeRegistry): EditorStore {
  let state: EditorState = {
    doc: initial,
    history: emptyHistory,
    gestureBase: null,
    selection: new Set(),
    time: 0,
    playing: false,
  };
  const listeners = new Set<() => void>();
  const set = (next: Partial<EditorState>) => {
    state = { ...state, ...next };
    for (const l of [...listeners]) l();
  };
  const apply = (doc: GraphDoc, change: Change) => applyChange(doc, change, registry);
  /** Drops selected ids that no longer exist. */
  const prune = (doc: GraphDoc, selection: ReadonlySet<string>) => {
    if (selection.size === 0) return selection;
    const ids = new Set(doc.nodes.map((n) => n.id));
    const kept = [...selection].filter((id) => ids.has(id));
    return kept.length === selection.size ? selection : new Set(kept);
  };
  const finishGesture = () => {
    if (state.gestureBase) set({ doc: state.gestureBase, gestureBase: null });
  };

  return {
    getState: () => state,
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    dispatch(change, label = describe(change)) {
      finishGesture();
      const after = apply(state.doc, change);
      set({
        doc: after,
        history: record(state.history, { before: state.doc, after, label }),
        selection: prune(after, state.selection),
      });
    },
    dispatchSilently(change) {
      const doc = apply(state.doc, change);
      // A silent change during a gesture also lands in the gesture's base so commit keeps it.
      set({ doc, ...(state.gestureBase ? { gestureBase: apply(state.gestureBase, change) } : {}) });
    },
    preview(change) {
      const base = state.gestureBase ?? state.doc;
      set({ gestureBase: base, doc: apply(base, change) });
    },
    commit(change, label = describe(change)) {
      const base = state.gestureBase ?? state.doc;
      const after = apply(base, change);
      set({
        doc: after,
        gestureBase: null,
        history: record(state.history, { before: base, after, label }),
        selection: prune(after, state.selection),
      });
    },
    cancelGesture: finishGesture,
    undo() {
      finishGesture();
      const r = undo(state.history, state.doc);
      if (r) set({ ...r, selection: prune(r.doc, state.selection) });
    },
    redo() {
      finishGesture();
      const r = redo(state.history, state.doc);
      if (r) set({ ...r, selection: prune(r.doc, state.selection) });
    },
    setSelection(ids) {
      const next = new Set(ids);
      if (next.size === state.selection.size && [...next].every((id) => state.selection.has(id))) return;
      set({ selection: next });
    },
    setTime: (time) => set({ time }),
    setPlaying: (playing) => set({ playing }),
  };
}
