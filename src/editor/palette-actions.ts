/**
 * What the palette does, as data: where it was opened (and by which dropped wire), and the one
 * change that adds the picked node there — wired to that wire when a port fits.
 */
import type { NodeDef } from '../../nodes/core/define-node.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { registry } from '../../nodes/types/index.ts';
import type { Change } from '../state/changes.ts';
import { idAllocator } from '../state/ids.ts';
import { portOfHandle } from './connection.ts';
import { compatiblePort, type WireFilter } from './fuzzy.ts';
import { clearSpot, NODE_WIDTH, sizer } from './layout.ts';
import { newNode } from './new-node.ts';

export interface PaletteState {
  /** Where it opened on screen (css px) and the same point in graph coordinates. */
  readonly screen: { x: number; y: number };
  readonly flow: { x: number; y: number };
  readonly filter?: WireFilter;
  /** The wire that opened the palette: its node, handle and which end was dragged. */
  readonly wire?: { nodeId: string; handle: string; side: 'source' | 'target' };
  /** Opened without a pointer position (the Add node button, Space with the pointer outside): the node goes where it covers no other. */
  readonly centred?: boolean;
}

/** The change adding `def` where the palette opened (one undo step) and the new node's id. */
export function addNodeChange(
  doc: GraphDoc,
  def: NodeDef,
  palette: PaletteState,
): { change: Change; nodeId: string } {
  // A node fed by a wire from its right (dragged from an input) goes to the left of the cursor.
  const x = palette.wire?.side === 'target' ? palette.flow.x - NODE_WIDTH : palette.flow.x;
  const placed = newNode(doc, def, [x, palette.flow.y - 20]);
  const node = palette.centred
    ? { ...placed, position: clearSpot(doc, placed, sizer(doc, registry)) }
    : placed;
  const changes: Change[] = [{ type: 'add-node', node }];
  const port = palette.wire && palette.filter ? compatiblePort(def, palette.filter) : null;
  if (palette.wire && port) {
    const other = { node: palette.wire.nodeId, port: portOfHandle(palette.wire.handle) };
    const mine = { node: node.id, port };
    const id = idAllocator({ ...doc, nodes: [...doc.nodes, node] })('e');
    changes.push({
      type: 'connect',
      edge: palette.wire.side === 'source' ? { id, from: other, to: mine } : { id, from: mine, to: other },
    });
  }
  return { change: { type: 'batch', changes }, nodeId: node.id };
}
