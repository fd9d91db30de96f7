/**
 * Frames in the React Flow canvas: their flow nodes (rebuilt from the document, selection kept
 * locally), the live move of a frame's nodes while its title bar is dragged, and the one undo
 * step at the drop (tools/frames.ts moveFrame).
 */
import { applyNodeChanges, type NodeChange } from '@xyflow/react';
import { type Dispatch, type SetStateAction, useCallback, useMemo, useRef, useState } from 'react';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import type { EditorStore } from '../../state/store.ts';
import type { KfNode } from '../flow-model.ts';
import { gridPosition } from '../new-node.ts';
import { FRAME_PREFIX, type FrameNode, toFrameNodes } from './FrameView.tsx';
import { moveFrame, nodesInFrame } from './frames.ts';

export function useFrames(doc: GraphDoc, store: EditorStore, setNodes: Dispatch<SetStateAction<KfNode[]>>) {
  const [selected, setSelected] = useState<ReadonlySet<string>>(new Set());
  /** React Flow's live position of a frame being dragged (the document moves only at the drop). */
  const [dragging, setDragging] = useState<{ id: string; x: number; y: number } | null>(null);
  const before = useRef<GraphDoc | null>(null);
  const frameNodes = useMemo(
    () =>
      toFrameNodes(doc.frames ?? [], selected).map((n) =>
        dragging?.id === n.id ? { ...n, position: { x: dragging.x, y: dragging.y } } : n,
      ),
    [doc.frames, selected, dragging],
  );

  const onFrameChanges = useCallback(
    (changes: NodeChange<FrameNode>[]) => {
      for (const c of changes)
        if (c.type === 'position' && c.position && c.dragging)
          setDragging({ id: c.id, x: c.position.x, y: c.position.y });
      if (!changes.some((c) => c.type === 'select')) return;
      const next = applyNodeChanges(changes, frameNodes);
      setSelected(new Set(next.filter((n) => n.selected).map((n) => n.id)));
    },
    [frameNodes],
  );

  /** While dragging: the frame's nodes follow it (React Flow state only). */
  const onFrameDrag = useCallback(
    (node: FrameNode) => {
      const base = before.current ?? store.getState().doc;
      before.current = base;
      const frame = node.data.frame;
      const [dx, dy] = [node.position.x - frame.position[0], node.position.y - frame.position[1]];
      setDragging({ id: node.id, x: node.position.x, y: node.position.y });
      const inside = new Set(nodesInFrame(base, frame));
      const at = new Map(base.nodes.map((n) => [n.id, n.position]));
      setNodes((prev) =>
        prev.map((n) => {
          const p = at.get(n.id);
          return inside.has(n.id) && p ? { ...n, position: { x: p[0] + dx, y: p[1] + dy } } : n;
        }),
      );
    },
    [store, setNodes],
  );

  /** The drop: frame and nodes move in the document as one undo step (snapped to whole units). */
  const onFrameDragStop = useCallback(
    (node: FrameNode) => {
      const base = before.current ?? store.getState().doc;
      before.current = null;
      setDragging(null);
      const frame = node.data.frame;
      const [x, y] = gridPosition(node.position.x, node.position.y);
      const change = moveFrame(base, frame.id, x - frame.position[0], y - frame.position[1]);
      if (change) store.dispatch(change, 'move frame');
    },
    [store],
  );

  const selectedFrameIds = useMemo(
    () => [...selected].map((id) => id.slice(FRAME_PREFIX.length)),
    [selected],
  );
  return { frameNodes, onFrameChanges, onFrameDrag, onFrameDragStop, selectedFrameIds };
}
