/**
 * Which nodes a frame carries (docs/architecture.md "Frames and reroute points"): a frame owns no
 * nodes in the document; the nodes whose top-left corner lies inside it move with it, and go
 * into a group with it when all of them are grouped.
 */
import type { GraphFrame, GraphNode } from './document.ts';

/** Ids of the nodes whose top-left corner lies inside the frame. */
export function nodesInFrame(nodes: readonly GraphNode[], frame: GraphFrame): string[] {
  const [fx, fy] = frame.position;
  const [w, h] = frame.size;
  return nodes
    .filter(({ position: [x, y] }) => x >= fx && x <= fx + w && y >= fy && y <= fy + h)
    .map((n) => n.id);
}
