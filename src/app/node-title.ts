/** The title a node's header shows (NodeView.tsx): its own label, else its type's name. */
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { nodeDef } from '../../nodes/graph/group-def.ts';

export function nodeTitle(doc: GraphDoc, id: string, registry: NodeRegistry): string {
  const node = doc.nodes.find((n) => n.id === id);
  if (!node) return id;
  return node.label?.trim() || nodeDef(registry, node)?.label || node.type;
}
