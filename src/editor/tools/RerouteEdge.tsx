/**
 * The editor's wire: a bezier curve, or — when it has reroute points — straight segments through
 * them, each point a dot you can drag (one undo step per drag) or double-click away.
 */
import { BaseEdge, type Edge, type EdgeProps, getBezierPath, useReactFlow } from '@xyflow/react';
import { memo } from 'react';
import type { Change } from '../../state/changes.ts';
import { useStore } from '../../state/use-store.ts';
import { gridPosition } from '../new-node.ts';
import { polylinePath } from './reroute.ts';

export type RerouteEdgeData = { via: readonly (readonly [number, number])[] };
export type KfEdge = Edge<RerouteEdgeData, 'kf'>;

function RerouteEdgeImpl(props: EdgeProps<KfEdge>) {
  const { id, sourceX, sourceY, targetX, targetY, data, style, interactionWidth } = props;
  const store = useStore();
  const flow = useReactFlow();
  const via = data?.via ?? [];
  const path =
    via.length === 0
      ? getBezierPath(props)[0]
      : polylinePath([[sourceX, sourceY], ...via, [targetX, targetY]]);
  const setVia = (next: readonly (readonly [number, number])[]): Change => ({
    type: 'set-via',
    edgeId: id,
    via: next,
  });
  const moved = (i: number, e: React.PointerEvent) => {
    const p = flow.screenToFlowPosition({ x: e.clientX, y: e.clientY });
    return setVia(via.map((q, j) => (j === i ? gridPosition(p.x, p.y) : q)));
  };
  return (
    <>
      <BaseEdge path={path} style={style} interactionWidth={interactionWidth} />
      {via.map(([x, y], i) => (
        // biome-ignore lint/a11y/useSemanticElements: an SVG dot on the canvas cannot be a <button>; dragged with the pointer
        <circle
          // biome-ignore lint/suspicious/noArrayIndexKey: a reroute point is its place on the wire
          key={i}
          className="kf-reroute nodrag nopan"
          cx={x}
          cy={y}
          r={6}
          fill={(style?.stroke as string) ?? '#888'}
          stroke="#111"
          role="button"
          aria-label="Reroute point"
          onPointerDown={(e) => {
            e.stopPropagation();
            (e.target as Element).setPointerCapture(e.pointerId);
          }}
          onPointerMove={(e) => {
            if ((e.target as Element).hasPointerCapture(e.pointerId)) store.preview(moved(i, e));
          }}
          onPointerUp={(e) => {
            if (!(e.target as Element).hasPointerCapture(e.pointerId)) return;
            (e.target as Element).releasePointerCapture(e.pointerId);
            if (store.getState().gestureBase) store.commit(moved(i, e), 'move reroute point');
          }}
          onDoubleClick={(e) => {
            e.stopPropagation();
            store.dispatch(setVia(via.filter((_, j) => j !== i)), 'remove reroute point');
          }}
        />
      ))}
    </>
  );
}

export const RerouteEdge = memo(RerouteEdgeImpl);
