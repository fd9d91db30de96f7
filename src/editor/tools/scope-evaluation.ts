/**
 * The evaluation as the graph editor shows it at one level of groups: evaluation runs on the
 * flattened graph (nodes/graph/flatten.ts), so its results and diagnostics name flattened ids.
 * At a level, a node inside it shows its own; a group node shows every diagnostic from inside it.
 */
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import type { Evaluation, NodeEvaluation } from '../../../nodes/graph/evaluate.ts';
import { idAtLevel, pathOf } from '../../../nodes/graph/flatten.ts';

/** The id at level `path` that flattened node `flatId` belongs to, or null when it is elsewhere. */
function localId(evaluation: Evaluation, flatId: string, path: readonly string[]): string | null {
  return idAtLevel(pathOf(evaluation.origin, flatId), path);
}

export function scopeEvaluation(evaluation: Evaluation, path: readonly string[]): Evaluation {
  if (path.length === 0 && evaluation.origin.size === 0) return evaluation;
  const nodes = new Map<string, NodeEvaluation>();
  for (const [id, result] of evaluation.nodes) {
    const local = localId(evaluation, id, path);
    // Only a node directly at this level has a result of its own (a group has none).
    if (local !== null && (evaluation.origin.get(id)?.length ?? 1) === path.length + 1)
      nodes.set(local, result);
  }
  const diagnostics: Diagnostic[] = [];
  for (const d of evaluation.diagnostics) {
    if (!d.nodeId) {
      if (path.length === 0) diagnostics.push(d);
      continue;
    }
    const local = localId(evaluation, d.nodeId, path);
    if (local !== null) diagnostics.push({ ...d, nodeId: local });
  }
  return { ...evaluation, nodes, diagnostics };
}
