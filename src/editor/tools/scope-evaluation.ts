/**
 * The evaluation as the graph editor shows it at one level of groups: evaluation runs on the
 * flattened graph (nodes/graph/flatten.ts), so its results and diagnostics name flattened ids.
 * At a level, a node inside it shows its own; a group node shows every diagnostic from inside it,
 * each saying which inner node it is about (nodes/graph/group-diagnostics.ts).
 */
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { Evaluation, NodeEvaluation } from '../../../nodes/graph/evaluate.ts';
import { idAtLevel, pathOf } from '../../../nodes/graph/flatten.ts';
import { diagnosticAtLevel } from '../../../nodes/graph/group-diagnostics.ts';
import { registry } from '../../../nodes/types/index.ts';

export function scopeEvaluation(
  evaluation: Evaluation,
  path: readonly string[],
  doc: Pick<GraphDoc, 'nodes'>,
): Evaluation {
  if (path.length === 0 && evaluation.origin.size === 0) return evaluation;
  const nodes = new Map<string, NodeEvaluation>();
  for (const [id, result] of evaluation.nodes) {
    const local = idAtLevel(pathOf(evaluation.origin, id), path);
    // Only a node directly at this level has a result of its own (a group has none).
    if (local !== null && (evaluation.origin.get(id)?.length ?? 1) === path.length + 1)
      nodes.set(local, result);
  }
  return {
    ...evaluation,
    nodes,
    diagnostics: scopeDiagnostics(evaluation.diagnostics, evaluation, path, doc),
  };
}

/**
 * Diagnostics that name flattened ids — the evaluation's, or the renderer's (a shader problem of an
 * element from inside a group) — as shown at the level `path`: those about nodes elsewhere are left out.
 */
export function scopeDiagnostics(
  diagnostics: readonly Diagnostic[],
  evaluation: Pick<Evaluation, 'origin'>,
  path: readonly string[],
  doc: Pick<GraphDoc, 'nodes'>,
): Diagnostic[] {
  const shown: Diagnostic[] = [];
  for (const d of diagnostics) {
    const at = diagnosticAtLevel(d, doc, evaluation.origin, path, registry);
    if (at) shown.push(at);
  }
  return shown;
}
