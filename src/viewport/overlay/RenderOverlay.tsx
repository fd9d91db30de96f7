/**
 * Direct manipulation in the render: the construction (points, infinite lines, circles, labels)
 * drawn over the picture, hover in both directions (pointer → onHoverNode, hoveredNodeIds →
 * highlight), and draggable handles whose moves become params patches (onPreview while dragging,
 * onCommit once on release; Shift snaps, Escape cancels). Mounted by the editor over the canvas.
 *
 * The pan/zoom handler of the pane must listen on an ancestor of this overlay (events bubble up
 * from it) and ignore a pointerdown whose `defaultPrevented` is set: that one grabbed a handle.
 */
import { type JSX, useMemo, useRef } from 'react';
import type { HandleItem, View } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { dragPatches, type NodePatch } from '../../../nodes/graph/drag-patches.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { OVERLAY_PX } from './constants.ts';
import { FigureOverlay } from './FigureOverlay.tsx';
import { hitShape } from './hit-test.ts';
import { KeptSides } from './KeptSides.tsx';
import { keptSideShapes } from './kept-side-shapes.ts';
import { OverlayShapes } from './OverlayShapes.tsx';
import { SnapGuides } from './SnapGuides.tsx';
import { placeHandles, placeOverlays, pxPerWorld, type Screen, toWorld } from './screen.ts';
import { snapHandle } from './snap-rules.ts';
import { useClickToPlace } from './use-click-to-place.ts';
import { useHandleKeyboard } from './use-handle-keyboard.ts';
import { type DragPlacer, useOverlayPointer } from './use-overlay-pointer.ts';

export type { NodePatch } from '../../../nodes/graph/drag-patches.ts';

export interface RenderOverlayProps {
  doc: GraphDoc;
  evaluation: Evaluation;
  view: View;
  width: number;
  height: number;
  /** The nodes drawn highlighted: one node's, or everything a hovered group's nodes draw. */
  hoveredNodeIds: ReadonlySet<string>;
  onHoverNode(id: string | null): void;
  /** Live while dragging (at most once per animation frame), no history. */
  onPreview(patches: NodePatch[]): void;
  /** On pointer-up after a drag: one undo step. */
  onCommit(patches: NodePatch[]): void;
  showLabels?: boolean;
  /** Presenting or embedded: the construction is drawn, but there is nothing to grab. */
  readOnly?: boolean;
  /** Inspect mode: a click explains the pixel, so handles do not grab (Alt-click never grabs either). */
  inspecting?: boolean;
}

const FALLBACK_COLOR = '#ffffff';

/**
 * A 2D handle drag: the handle keeps its offset from the pointer (it does not jump to it) and,
 * with Shift, snaps (snap-rules.ts) to the grid, angles and tangencies of the construction.
 */
function grabInPlane(screen: Screen, target: HandleItem, css: Vec2, evaluation: Evaluation): DragPlacer {
  const p = toWorld(screen, css);
  const offset: Vec2 = [target.at[0] - p[0], target.at[1] - p[1]];
  return (at, shift) => {
    const w = toWorld(screen, at);
    const want: Vec2 = [w[0] + offset[0], w[1] + offset[1]];
    const snap = shift ? snapHandle(evaluation.scene.overlays, target, want, pxPerWorld(screen)) : null;
    return { patches: dragPatches(evaluation, target, snap ? snap.at : want), snap };
  };
}

const NONE: ReadonlySet<string> = new Set();

export function RenderOverlay(props: RenderOverlayProps): JSX.Element {
  const { evaluation, view, width, height, hoveredNodeIds, showLabels = true, readOnly = false } = props;
  const ref = useRef<SVGSVGElement>(null);
  const screen = useMemo<Screen>(() => ({ view, width, height }), [view, width, height]);
  // A pane not laid out yet (0 × 0) has no pixel mapping: draw nothing rather than NaNs.
  const sized = width > 0 && height > 0;
  const items = useMemo(
    () => (sized ? placeOverlays(evaluation.scene.overlays, screen) : []),
    [sized, evaluation, screen],
  );
  const handles = useMemo(
    () =>
      placeHandles(
        sized && !readOnly ? evaluation.scene.handles : [],
        (id) => evaluation.analysis.nodes.get(id)?.def?.color ?? FALLBACK_COLOR,
        screen,
      ),
    [sized, readOnly, evaluation, screen],
  );
  const keptSides = useMemo(
    () => (sized ? keptSideShapes(evaluation.scene.elements, screen) : []),
    [sized, evaluation, screen],
  );
  const { drag, hoverHandle } = useOverlayPointer<HandleItem>(ref, {
    evaluation,
    handles,
    hoverGeometry: (css) => {
      const j = hitShape(
        items.map((it) => it.shape),
        css,
        OVERLAY_PX.geometryHit,
      );
      return j >= 0 ? items[j].nodeId : null;
    },
    grab: (target, css, atDown) => grabInPlane(screen, target, css, atDown),
    onHoverNode: props.onHoverNode,
    onPreview: props.onPreview,
    onCommit: props.onCommit,
    inspecting: props.inspecting ?? false,
  });
  // Registered after the handle drags (see use-click-to-place.ts): the first placeable handle.
  const placeable = readOnly ? undefined : evaluation.scene.handles.find((h) => h.placeOnClick);
  useClickToPlace(ref, {
    place: placeable && sized ? (css) => dragPatches(evaluation, placeable, toWorld(screen, css)) : null,
    onCommit: props.onCommit,
    inspecting: props.inspecting ?? false,
  });
  const keyboard = useHandleKeyboard(props, screen, !readOnly && !props.inspecting);
  const cursor = props.inspecting
    ? 'crosshair'
    : drag
      ? 'grabbing'
      : hoverHandle
        ? 'grab'
        : placeable
          ? 'crosshair'
          : undefined;
  return (
    <svg
      ref={ref}
      className="kf-render-overlay"
      width={width}
      height={height}
      viewBox={`0 0 ${width} ${height}`}
      // A group when its handles take the focus (an img's children are hidden from screen readers).
      role={keyboard ? 'group' : 'img'}
      aria-label={
        readOnly
          ? 'Construction overlay (read-only)'
          : 'Construction overlay: drag the handles, or focus one and use the arrow keys, to move points and circles'
      }
      style={{
        position: 'absolute',
        inset: 0,
        touchAction: 'none',
        userSelect: 'none',
        overflow: 'hidden',
        cursor,
      }}
    >
      {sized && <FigureOverlay scene={evaluation.scene} screen={screen} />}
      <KeptSides
        shapes={keptSides}
        colorOf={(id) => evaluation.analysis.nodes.get(id)?.def?.color ?? FALLBACK_COLOR}
        hoveredNodeIds={drag ? NONE : hoveredNodeIds}
      />
      <OverlayShapes
        items={items}
        handles={handles}
        width={width}
        height={height}
        hoveredNodeIds={drag ? new Set([drag.target.nodeId]) : hoveredNodeIds}
        hoverHandle={hoverHandle}
        dragTarget={drag?.target ?? null}
        showLabels={showLabels}
        keyboard={keyboard}
      />
      {drag?.snap && <SnapGuides screen={screen} guide={drag.snap.guide} at={drag.snap.at} />}
    </svg>
  );
}
