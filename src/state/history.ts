/**
 * Undo history as (before, after) document snapshots. Documents are immutable and changes keep
 * untouched parts by identity, so a snapshot costs little. Pan/zoom is not history: undo/redo keep
 * the current view (and 3D camera), except for a step that itself changed it (opening a document),
 * whose undo brings it back too.
 */
import type { GraphDoc } from '../../nodes/graph/document.ts';

export interface HistoryStep {
  readonly before: GraphDoc;
  readonly after: GraphDoc;
  /** What the step did, for the Undo button's tooltip ("Undo move nodes"). */
  readonly label: string;
}

export interface History {
  readonly past: readonly HistoryStep[];
  readonly future: readonly HistoryStep[];
}

/** At most this many steps are kept; older ones are dropped. */
export const HISTORY_LIMIT = 200;

export const emptyHistory: History = { past: [], future: [] };

/** Records a step (clearing redo). A step that changed nothing is not recorded. */
export function record(history: History, step: HistoryStep): History {
  if (step.before === step.after) return history;
  const past = [...history.past, step];
  return { past: past.length > HISTORY_LIMIT ? past.slice(past.length - HISTORY_LIMIT) : past, future: [] };
}

/**
 * `target` with the current view and 3D camera (view state, docs/architecture.md "Data flow"),
 * each unless the step moved it itself.
 */
function keepView(step: HistoryStep, target: GraphDoc, current: GraphDoc): GraphDoc {
  let doc = target;
  if (step.before.view === step.after.view && doc.view !== current.view) doc = { ...doc, view: current.view };
  if (step.before.camera3d === step.after.camera3d && doc.camera3d !== current.camera3d) {
    const { camera3d: _old, ...rest } = doc;
    doc = current.camera3d === undefined ? rest : { ...rest, camera3d: current.camera3d };
  }
  return doc;
}

/** Undoes the last step: the document before it (with the current view), or null when none. */
export function undo(history: History, current: GraphDoc): { history: History; doc: GraphDoc } | null {
  const step = history.past.at(-1);
  if (!step) return null;
  return {
    history: { past: history.past.slice(0, -1), future: [step, ...history.future] },
    doc: keepView(step, step.before, current),
  };
}

export function redo(history: History, current: GraphDoc): { history: History; doc: GraphDoc } | null {
  const step = history.future[0];
  if (!step) return null;
  return {
    history: { past: [...history.past, step], future: history.future.slice(1) },
    doc: keepView(step, step.after, current),
  };
}
