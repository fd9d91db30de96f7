/** Evaluates one node of a registered type on its own (params as in a document) and returns its result. */
import type { NodeEvaluation } from '../../../nodes/graph/evaluate.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from './doc.ts';

export function evalNode(type: string, params: Record<string, unknown> = {}, time = 0): NodeEvaluation {
  const ev = evaluateGraph(doc([node('n', type, params)]), registry, { time });
  return ev.nodes.get('n')!;
}

/** Codes of the node's diagnostics with the given severity. */
export const codes = (r: NodeEvaluation, severity: 'error' | 'warning' = 'error'): string[] =>
  r.diagnostics.filter((d) => d.severity === severity).map((d) => d.code);

/** The node type's definition (to call overlay, handles and drag directly). */
export const defOf = (type: string) => registry.get(type)!;

/**
 * What every node type promises with its defaults: no errors, every declared output present and
 * finite, a doc line, a label on every input and output, a default on every inline-editable input.
 */
export function checkDefaults(type: string): NodeEvaluation {
  const def = defOf(type);
  const r = evalNode(type);
  const problems: string[] = [...codes(r)];
  if (!def.doc) problems.push('no doc');
  for (const [name, spec] of Object.entries(def.inputs)) {
    if (!spec.label) problems.push(`input ${name} has no label`);
    if (!spec.optional && spec.type !== 'element' && spec.type !== 'tile' && spec.default === undefined)
      problems.push(`input ${name} has no default`);
  }
  for (const [name, spec] of Object.entries(def.outputs)) {
    if (!spec.label) problems.push(`output ${name} has no label`);
    if (r.outputs?.[name] === undefined) problems.push(`output ${name} missing`);
  }
  if (problems.length > 0) throw new Error(`${type}: ${problems.join('; ')}`);
  return r;
}
