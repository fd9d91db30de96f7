/** Imports a Flower fixture and evaluates the result (throws when the import itself fails). */
import type { Diagnostic } from '../../../../../nodes/core/diagnostics.ts';
import type { Scene } from '../../../../../nodes/core/scene.ts';
import type { GraphDoc } from '../../../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../../nodes/types/index.ts';
import { importFlower } from '../../../../../src/io/flower/import.ts';

export function imported(json: unknown): {
  doc: GraphDoc;
  notes: Diagnostic[];
  scene: Scene;
  errors: string[];
} {
  const r = importFlower(json);
  if (!r.ok) throw new Error(r.diagnostics.map((d) => d.message).join('\n'));
  const ev = evaluateGraph(r.doc, registry);
  const errors = ev.diagnostics.filter((d) => d.severity === 'error').map((d) => `${d.nodeId}: ${d.message}`);
  return { doc: r.doc, notes: r.notes, scene: ev.scene, errors };
}

export const messages = (notes: readonly Diagnostic[]): string[] => notes.map((n) => n.message);
