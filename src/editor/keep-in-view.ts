/**
 * Keeps a node on screen: the inspected one (opening the docked inspector narrows the canvas, and
 * a node near its right edge would slip out of view) or one just added (the Add node button puts
 * it beside the others, maybe past the edge); the graph pans just enough to show it.
 */

import { type Edge, useReactFlow } from '@xyflow/react';
import { type RefObject, useEffect } from 'react';
import { motionMs } from '../ui/motion.ts';
import type { KfNode } from './flow-model.ts';

/** A node is brought this far inside the canvas's edges (css px). */
const MARGIN_PX = 16;
/** Frames to wait for a new node's measured size. */
const MAX_WAIT_FRAMES = 10;

/**
 * How far to move a span [lo, lo + size] so it lies inside [margin, avail − margin]: 0 when it
 * already does; a span too long to fit gets its start shown.
 */
export function shiftIntoView(lo: number, size: number, avail: number, margin = MARGIN_PX): number {
  if (lo < margin) return margin - lo;
  const over = lo + size - (avail - margin);
  return over > 0 ? -Math.min(over, lo - margin) : 0;
}

/** `layout`: whatever changes the canvas's width (the docked panel opening): the check runs again. */
export function useKeepInView(
  nodeId: string | undefined,
  pane: RefObject<HTMLElement | null>,
  layout: unknown = null,
): void {
  const flow = useReactFlow<KfNode, Edge>();
  // biome-ignore lint/correctness/useExhaustiveDependencies: `layout` only says when to look again
  useEffect(() => {
    if (!nodeId) return;
    // After the layout that opened the panel, so the canvas has its new width; a node just added
    // is measured a frame or two after it appears, so wait for its size (a few frames at most).
    let frame = 0;
    let tries = 0;
    const show = () => {
      const node = flow.getInternalNode(nodeId);
      const el = pane.current;
      if (!node || !el) return;
      if (!node.measured.width && ++tries < MAX_WAIT_FRAMES) {
        frame = requestAnimationFrame(show);
        return;
      }
      const { x, y, zoom } = flow.getViewport();
      const at = node.internals.positionAbsolute;
      const dx = shiftIntoView(at.x * zoom + x, (node.measured.width ?? 0) * zoom, el.clientWidth);
      const dy = shiftIntoView(at.y * zoom + y, (node.measured.height ?? 0) * zoom, el.clientHeight);
      if (dx !== 0 || dy !== 0)
        void flow.setViewport({ x: x + dx, y: y + dy, zoom }, { duration: motionMs(150) });
    };
    frame = requestAnimationFrame(show);
    return () => cancelAnimationFrame(frame);
  }, [nodeId, flow, pane, layout]);
}
