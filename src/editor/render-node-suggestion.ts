/**
 * The node the empty inspector offers to open: the render node that makes the picture, when it is
 * at the level of the graph on screen. Its settings (samples, the 3D view's volume, reflections and
 * environment) are what a newcomer most often looks for, and in a large graph it is many Tab
 * presses away (every node's ports and fields come first).
 */
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';

export interface NodeSuggestion {
  readonly id: string;
  /** What the button calls it: the node's label, else its type's name. */
  readonly title: string;
}

export function renderNodeSuggestion(doc: GraphDoc, evaluation: Evaluation): NodeSuggestion | undefined {
  const id = evaluation.scene3d?.renderNodeId ?? evaluation.scene.renderNodeId;
  const node = id ? doc.nodes.find((n) => n.id === id) : undefined;
  if (!node) return undefined;
  return { id: node.id, title: node.label ?? registry.get(node.type)?.label ?? node.type };
}
