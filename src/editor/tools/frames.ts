/**
 * Frames: titled, coloured backdrops behind nodes (docs/architecture.md "Frames and reroute
 * points"). A frame owns no nodes in the document; the nodes whose top-left corner lies inside it
 * when a drag begins move with it. Pure helpers: the editor turns them into one undo step each.
 */
import type { GraphDoc, GraphFrame } from '../../../nodes/graph/document.ts';
import { nodesInFrame as nodesIn } from '../../../nodes/graph/frames.ts';
import { registry } from '../../../nodes/types/index.ts';
import type { Change } from '../../state/changes.ts';
import { idAllocator } from '../../state/ids.ts';
import { sizer } from '../layout.ts';

/** Room around the framed nodes, and above them for the title bar. */
const PAD = 24;
const TITLE = 32;
export const FRAME_COLOURS = ['#3b4a6b', '#4a3b6b', '#2f5b4a', '#6b4a2f', '#5b2f3b'] as const;

/** A new frame around the selected nodes (null when none is selected). */
export function frameAround(doc: GraphDoc, selection: ReadonlySet<string>): Change | null {
  const nodes = doc.nodes.filter((n) => selection.has(n.id));
  if (nodes.length === 0) return null;
  const size = sizer(doc, registry);
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const n of nodes) {
    const s = size(n);
    x0 = Math.min(x0, n.position[0]);
    y0 = Math.min(y0, n.position[1]);
    x1 = Math.max(x1, n.position[0] + s.width);
    y1 = Math.max(y1, n.position[1] + s.height);
  }
  const count = doc.frames?.length ?? 0;
  const frame: GraphFrame = {
    id: idAllocator(doc)('frame'),
    title: `Frame ${count + 1}`,
    color: FRAME_COLOURS[count % FRAME_COLOURS.length],
    position: [x0 - PAD, y0 - PAD - TITLE],
    size: [x1 - x0 + 2 * PAD, y1 - y0 + 2 * PAD + TITLE],
  };
  return { type: 'put-frame', frame };
}

/** Ids of the nodes whose top-left corner lies inside the frame: they move with it. */
export const nodesInFrame = (doc: GraphDoc, frame: GraphFrame): string[] => nodesIn(doc.nodes, frame);

/**
 * Moving a frame by (dx, dy): the frame and the nodes that were inside it at `before`, as ONE
 * change (one undo step).
 */
export function moveFrame(before: GraphDoc, frameId: string, dx: number, dy: number): Change | null {
  const frame = before.frames?.find((f) => f.id === frameId);
  if (!frame || (dx === 0 && dy === 0)) return null;
  const inside = new Set(nodesInFrame(before, frame));
  const moves = before.nodes
    .filter((n) => inside.has(n.id))
    .map((n) => ({ nodeId: n.id, position: [n.position[0] + dx, n.position[1] + dy] as [number, number] }));
  const moved: GraphFrame = { ...frame, position: [frame.position[0] + dx, frame.position[1] + dy] };
  return {
    type: 'batch',
    changes: [
      { type: 'put-frame', frame: moved },
      { type: 'move-nodes', moves },
    ],
  };
}
