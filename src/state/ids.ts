/** Fresh ids for nodes and edges: `prefix` + the smallest number not in use in the document. */
import type { GraphDoc } from '../../nodes/graph/document.ts';

/** A generator of ids unused in `doc` (and unused by earlier calls of the same generator). */
export function idAllocator(doc: GraphDoc): (prefix: string) => string {
  const used = new Set<string>([...doc.nodes.map((n) => n.id), ...doc.edges.map((e) => e.id)]);
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
