/**
 * What the render pane says when there is no picture: the first error of a render node or of a
 * node wired into it (a tile with a bad field, …) when there is one, else how to get a picture.
 */
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';

export function renderHint(doc: GraphDoc, evaluation: Evaluation): string | null {
  if (evaluation.scene.renderNodeId !== null || doc.nodes.length === 0) return null;
  const renders = doc.nodes.filter((n) => n.type === 'render').map((n) => n.id);
  // The render nodes and everything upstream of them.
  const upstream = new Set(renders);
  for (let grew = true; grew; ) {
    grew = false;
    for (const e of doc.edges) {
      if (upstream.has(e.to.node) && !upstream.has(e.from.node)) {
        upstream.add(e.from.node);
        grew = true;
      }
    }
  }
  const error = evaluation.diagnostics.find(
    (d) => d.severity === 'error' && d.nodeId !== undefined && upstream.has(d.nodeId),
  );
  if (renders.length > 0 && error)
    return `No picture: node "${error.nodeId}" has an error (${error.code}): ${error.message}`;
  return 'Wire elements into a Render node to see a picture.';
}
