/**
 * A diagnostic's fix (nodes/core/diagnostics.ts DiagnosticFix) → the params patches the store
 * applies as ONE undo step (pure). Handle moves go through the render's drag mapping, so a move
 * aimed at a wired point moves the upstream node that owns it, exactly like a drag in the picture.
 */
import type { DiagnosticFix } from '../../nodes/core/diagnostics.ts';
import { dragPatches, type NodePatch } from '../../nodes/graph/drag-patches.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';

export function fixPatches(evaluation: Evaluation, fix: DiagnosticFix): NodePatch[] {
  const byNode = new Map<string, Record<string, unknown>>();
  const add = (patches: readonly NodePatch[]) => {
    for (const p of patches) byNode.set(p.nodeId, { ...(byNode.get(p.nodeId) ?? {}), ...p.params });
  };
  add((fix.params ?? []).map((p) => ({ nodeId: p.nodeId, params: { ...p.params } })));
  for (const m of fix.moves ?? []) add(dragPatches(evaluation, { nodeId: m.nodeId, handle: m.handle }, m.to));
  return [...byNode].map(([nodeId, params]) => ({ nodeId, params }));
}
