/**
 * Frames the graph whenever a document is loaded (`frameKey` changes) once React Flow has measured
 * the new nodes: fit it, but never below a readable zoom; a graph taller (wider) than the pane at
 * that zoom is aligned to its top (left: where the construction starts) instead of being cut at
 * both ends.
 */
import { type Edge, useNodesInitialized, useReactFlow } from '@xyflow/react';
import { type RefObject, useEffect, useRef } from 'react';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { KfNode } from './flow-model.ts';
import { FIT_VIEW } from './layout.ts';

const TOP_MARGIN_PX = 56;
const LEFT_MARGIN_PX = 24;

export function useFrameGraph(
  frameKey: number,
  doc: GraphDoc,
  nodes: readonly KfNode[],
  pane: RefObject<HTMLElement | null>,
): void {
  const flow = useReactFlow<KfNode, Edge>();
  const initialized = useNodesInitialized();
  const pending = useRef(true);
  // biome-ignore lint/correctness/useExhaustiveDependencies: frameKey is the trigger itself
  useEffect(() => {
    pending.current = true;
  }, [frameKey]);
  useEffect(() => {
    if (!pending.current) return;
    if (doc.nodes.length === 0) {
      pending.current = false; // an empty graph: nothing to frame (and the next node must not jump)
      return;
    }
    // Wait until React Flow shows (and has measured) exactly this document's nodes.
    const current = nodes.length === doc.nodes.length && nodes.every((n, i) => n.data.node === doc.nodes[i]);
    if (!current || !initialized || nodes.some((n) => !n.measured)) return;
    pending.current = false;
    void flow.fitView(FIT_VIEW).then(() => {
      const fitted = flow.getViewport();
      const { zoom } = fitted;
      const bounds = flow.getNodesBounds(flow.getNodes());
      const height = pane.current?.clientHeight ?? 0;
      const width = pane.current?.clientWidth ?? 0;
      const tooTall = bounds.height * zoom + 2 * TOP_MARGIN_PX > height;
      const tooWide = bounds.width * zoom + 2 * LEFT_MARGIN_PX > width;
      if (tooTall || tooWide) {
        void flow.setViewport({
          x: tooWide ? LEFT_MARGIN_PX - bounds.x * zoom : fitted.x,
          y: tooTall ? TOP_MARGIN_PX - bounds.y * zoom : fitted.y,
          zoom,
        });
      }
    });
  }, [initialized, doc, nodes, flow, pane]);
}
