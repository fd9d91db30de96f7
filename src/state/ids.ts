/** Fresh ids for nodes and edges: `prefix` + the smallest number not in use in the document. */
import type { GraphDoc, GraphEdge, GraphNode } from '../../nodes/graph/document.ts';

/** Every node and edge id, inside groups too (a new id then never shadows a grouped node's). */
function collectIds(
  nodes: readonly GraphNode[],
  edges: readonly GraphEdge[],
  into: Set<string>,
): Set<string> {
  for (const n of nodes) {
    into.add(n.id);
    if (n.group) collectIds(n.group.nodes, n.group.edges, into);
  }
  for (const e of edges) into.add(e.id);
  return into;
}

/** A generator of ids unused in `doc` (and unused by earlier calls of the same generator). */
export function idAllocator(doc: Pick<GraphDoc, 'nodes' | 'edges' | 'frames'>): (prefix: string) => string {
  const used = collectIds(doc.nodes, doc.edges, new Set((doc.frames ?? []).map((f) => f.id)));
  return (prefix) => {
    const base = prefix.replace(/[^a-z0-9]+/gi, '-').replace(/^-|-$/g, '') || 'n';
    for (let i = 1; ; i++) {
      const id = `${base}${i}`;
      if (!used.has(id)) {
        used.add(id);
        return id;
      }
    }
  };
}
