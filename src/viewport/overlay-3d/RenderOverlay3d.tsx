/**
 * Direct manipulation in the 3D view: each 3D node's wireframe (points, sphere outlines, plane
 * patches, boxes) drawn over the picture in its colour, hover both ways, and draggable handles. A
 * handle moves in the plane through it parallel to the screen (camera-3d.ts pointOnScreenPlane);
 * the new position goes through dragPatches3d to the same preview / commit path as a 2D drag, so
 * a drag only changes values (uniforms) and never recompiles. From the keyboard, Tab reaches each
 * handle (named for a screen reader) and arrows / Page Up / Page Down move it (handle-keys-3d.ts).
 */
import { type JSX, useMemo, useRef } from 'react';
import type { Camera3d, Handle3dItem, Scene3d } from '../../../nodes/core/scene-3d.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { NodePatch } from '../../../nodes/graph/drag-patches.ts';
import { dragPatches3d } from '../../../nodes/graph/drag-patches-3d.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { type PaneSize, pointOnScreenPlane } from '../camera-3d.ts';
import { OVERLAY_PX } from '../overlay/constants.ts';
import { HandleKnobs, LABEL_COLOR, OUTLINE_COLOR } from '../overlay/OverlayShapes.tsx';
import { fmt, handleKeyboard } from '../overlay/use-handle-keyboard.ts';
import { type DragPlacer, useOverlayPointer } from '../overlay/use-overlay-pointer.ts';
import { handleKeyPatches3d } from './handle-keys-3d.ts';
import {
  itemNear,
  pathData,
  placeHandles3d,
  placeOverlays3d,
  type Screen3dHandle,
  type Screen3dItem,
} from './project-overlays.ts';

export interface RenderOverlay3dProps {
  evaluation: Evaluation;
  scene: Scene3d;
  camera: Camera3d;
  width: number;
  height: number;
  /** The nodes drawn highlighted: one node's, or everything a hovered group's nodes draw. */
  hoveredNodeIds: ReadonlySet<string>;
  onHoverNode(id: string | null): void;
  /** Live while dragging (at most once per animation frame), no history. */
  onPreview(patches: NodePatch[]): void;
  /** On pointer-up after a drag: one undo step. */
  onCommit(patches: NodePatch[]): void;
  /** Presenting or embedded: the construction is drawn, but there is nothing to grab (as in 2D). */
  readOnly?: boolean;
  /** Inspect mode: a click explains the pixel under it, so no handle is grabbed (as in 2D). */
  inspecting?: boolean;
}

const FALLBACK_COLOR = '#ffffff';

/**
 * A 3D handle drag: the handle keeps its pixel offset from the pointer and moves in the plane
 * through where it was, parallel to the screen.
 */
function grabOnScreenPlane(
  camera: Camera3d,
  pane: PaneSize,
  target: Handle3dItem & { readonly x: number; readonly y: number },
  css: Vec2,
  evaluation: Evaluation,
): DragPlacer {
  const ox = target.x - css[0];
  const oy = target.y - css[1];
  return (at) => {
    const to = pointOnScreenPlane(camera, pane, target.at, at[0] + ox, at[1] + oy);
    return { patches: to ? dragPatches3d(evaluation, target, to) : [], snap: null };
  };
}

function Wireframe({ item, hot }: { item: Screen3dItem; hot: boolean }): JSX.Element {
  const w = hot ? OVERLAY_PX.strokeHover : OVERLAY_PX.stroke;
  const d = item.lines.map(pathData).join('');
  return (
    <g data-node={item.nodeId} fill="none" strokeLinejoin="round">
      {d && hot && <path d={d} stroke={item.color} strokeWidth={w + 8} opacity={0.25} />}
      {d && <path d={d} stroke={OUTLINE_COLOR} strokeWidth={w + 2 * OVERLAY_PX.outline} />}
      {d && <path d={d} stroke={item.color} strokeWidth={w} />}
      {item.dot && (
        <circle
          cx={item.dot[0]}
          cy={item.dot[1]}
          r={OVERLAY_PX.pointRadius + (hot ? 1.5 : 0)}
          fill={item.color}
          stroke={OUTLINE_COLOR}
          strokeWidth={OVERLAY_PX.outline}
        />
      )}
    </g>
  );
}

/** Where a label goes: beside the dot, else beside the first point of the first line. */
function labelAt(item: Screen3dItem): Vec2 | null {
  const p = item.dot ?? item.lines[0]?.[0];
  return p ? [p[0] + OVERLAY_PX.labelOffset, p[1] - OVERLAY_PX.labelOffset] : null;
}

export function RenderOverlay3d(props: RenderOverlay3dProps): JSX.Element {
  const { evaluation, scene, camera, width, height, hoveredNodeIds, readOnly = false } = props;
  const ref = useRef<SVGSVGElement>(null);
  const sized = width > 0 && height > 0;
  const pane = useMemo<PaneSize>(() => ({ width, height }), [width, height]);
  const items = useMemo(
    () => (sized ? placeOverlays3d(scene.overlays, camera, pane) : []),
    [sized, scene, camera, pane],
  );
  const handles = useMemo(
    () =>
      (sized && !readOnly ? placeHandles3d(scene.handles, camera, pane) : []).map((h) => ({
        item: h,
        at: [h.x, h.y] as Vec2,
        color: evaluation.analysis.nodes.get(h.nodeId)?.def?.color ?? FALLBACK_COLOR,
      })),
    [sized, readOnly, scene, camera, pane, evaluation],
  );
  const { drag, hoverHandle } = useOverlayPointer(ref, {
    evaluation,
    handles,
    hoverGeometry: (css) => itemNear(items, css, OVERLAY_PX.geometryHit),
    grab: (target, css, atDown) => grabOnScreenPlane(camera, pane, target, css, atDown),
    onHoverNode: props.onHoverNode,
    onPreview: props.onPreview,
    onCommit: props.onCommit,
    inspecting: props.inspecting ?? false,
  });
  const { onCommit } = props;
  const keyboard = useMemo(() => {
    if (readOnly || props.inspecting) return undefined;
    const nodeName = (id: string) => {
      const n = evaluation.analysis.nodes.get(id);
      const type = n?.def?.label ?? 'node';
      return n?.node.label ? `${n.node.label}, ${type}` : type;
    };
    return handleKeyboard<Screen3dHandle>(
      nodeName,
      (h) =>
        `at ${h.at.map(fmt).join(', ')}: arrow keys move it across the screen, Page Up and Page Down away and nearer`,
      (h, at, e) => handleKeyPatches3d(e, h, at[0], at[1], camera, pane, evaluation),
      onCommit,
    );
  }, [readOnly, props.inspecting, evaluation, camera, pane, onCommit]);
  const hot = drag ? new Set([drag.target.nodeId]) : hoveredNodeIds;
  // Keys: the node id and how many of that node's items came before (a node may draw several).
  const wireframes: JSX.Element[] = [];
  const labels: JSX.Element[] = [];
  const seen = new Map<string, number>();
  const labelled = new Set<string>();
  for (const item of items) {
    const n = seen.get(item.nodeId) ?? 0;
    seen.set(item.nodeId, n + 1);
    wireframes.push(<Wireframe key={`${item.nodeId}:${n}`} item={item} hot={hot.has(item.nodeId)} />);
    const at = item.label && !labelled.has(item.nodeId) ? labelAt(item) : null;
    if (at) labelled.add(item.nodeId);
    if (at)
      labels.push(
        <text key={item.nodeId} x={at[0]} y={at[1]} className="kf-overlay-label">
          {item.label}
        </text>,
      );
  }
  return (
    <svg
      ref={ref}
      className="kf-render-overlay"
      width={width}
      height={height}
      viewBox={`0 0 ${width} ${height}`}
      // A group when its handles take the focus (an img's children are hidden from screen readers,
      // and a focusable handle inside an img is the nested control axe-core reports).
      role={keyboard && handles.length > 0 ? 'group' : 'img'}
      aria-label={
        readOnly
          ? '3D construction overlay (read-only)'
          : '3D construction overlay: drag the handles, or focus one and use the arrow keys (Page Up and Page Down along the line of sight), to move points and spheres'
      }
      style={{
        position: 'absolute',
        inset: 0,
        touchAction: 'none',
        userSelect: 'none',
        overflow: 'hidden',
        cursor: props.inspecting ? 'crosshair' : drag ? 'grabbing' : hoverHandle ? 'grab' : undefined,
      }}
    >
      <g>{wireframes}</g>
      <g
        fontSize={OVERLAY_PX.labelFont}
        fontFamily="system-ui, sans-serif"
        fontWeight={600}
        fill={LABEL_COLOR}
        stroke={OUTLINE_COLOR}
        strokeWidth={3}
        paintOrder="stroke"
        strokeLinejoin="round"
      >
        {labels}
      </g>
      <HandleKnobs
        handles={handles}
        hoveredNodeIds={hoveredNodeIds}
        hoverHandle={hoverHandle}
        dragTarget={drag?.target ?? null}
        keyboard={keyboard}
      />
    </svg>
  );
}
