/** A fresh node of a type, placed at a graph position, with an id unused in the document. */
import type { NodeDef } from '../../nodes/core/define-node.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc, GraphNode } from '../../nodes/graph/document.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { idAllocator } from '../state/ids.ts';
import { titleAllocator, withTitle } from '../state/titles.ts';

/** Whole graph units; `+ 0` turns Math.round's −0 into 0 so a saved position reads back equal. */
export const gridPosition = (x: number, y: number): [number, number] => [
  Math.round(x) + 0,
  Math.round(y) + 0,
];

/**
 * Params stay empty: the type's defaults apply until the user edits a value. The node gets a
 * title of its own when its type's name is taken ("Line reflection 2", state/titles.ts).
 */
export function newNode(
  doc: GraphDoc,
  def: NodeDef,
  position: readonly [number, number],
  registry: NodeRegistry = appRegistry,
): GraphNode {
  const node: GraphNode = {
    id: idAllocator(doc)(def.type),
    type: def.type,
    version: def.version,
    position: gridPosition(position[0], position[1]),
    params: {},
  };
  return withTitle(node, titleAllocator(doc.nodes, registry));
}
