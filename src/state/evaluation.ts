/** Evaluation of the current document, memoised on (document, time): one evaluation per change. */
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { type Evaluation, evaluateGraph } from '../../nodes/graph/evaluate.ts';

export function createEvaluator(registry: NodeRegistry): (doc: GraphDoc, time: number) => Evaluation {
  let last: { doc: GraphDoc; time: number; evaluation: Evaluation } | null = null;
  return (doc, time) => {
    if (last && last.doc === doc && last.time === time) return last.evaluation;
    const evaluation = evaluateGraph(doc, registry, { time });
    last = { doc, time, evaluation };
    return evaluation;
  };
}
