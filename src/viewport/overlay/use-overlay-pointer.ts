/**
 * Pointer handling of the render overlay: hover (handles, then geometry) and handle drags with
 * pointer capture, Shift snapping, previews throttled to animation frames, one commit on release
 * and Escape to cancel. Listeners are native (not React's delegated ones) so that
 * `preventDefault()` on a grabbed handle is already set when the pointerdown bubbles to the pan/zoom
 * handler of the pane; every other event goes through untouched, so the view pans and pinches.
 */
import { type RefObject, useEffect, useRef, useState } from 'react';
import type { HandleItem } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { dragPatches, type NodePatch, originalParams } from '../../../nodes/graph/drag-patches.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { OVERLAY_PX } from './constants.ts';
import { hitHandle, hitShape } from './hit-test.ts';
import { pxPerWorld, type Screen, type ScreenHandle, type ScreenItem, toWorld } from './screen.ts';
import { type SnapGuide, snapHandle } from './snap-rules.ts';

export interface PointerInputs {
  readonly evaluation: Evaluation;
  readonly screen: Screen;
  readonly items: readonly ScreenItem[];
  readonly handles: readonly ScreenHandle[];
  readonly onHoverNode: (id: string | null) => void;
  readonly onPreview: (patches: NodePatch[]) => void;
  readonly onCommit: (patches: NodePatch[]) => void;
  /** Inspect mode: no handle grabs (a click explains the pixel instead). */
  readonly inspecting: boolean;
}

/** What the overlay draws about the drag in progress. */
export interface DragView {
  readonly target: HandleItem;
  readonly snap: { readonly guide: SnapGuide; readonly at: Vec2 } | null;
}

export interface OverlayPointer {
  readonly drag: DragView | null;
  /** The handle under the pointer (grab cursor, bigger handle), when not dragging. */
  readonly hoverHandle: HandleItem | null;
}

interface DragState {
  readonly pointerId: number;
  readonly target: HandleItem;
  /** Evaluation at pointer-down: every move maps from it, so previews never feed back. */
  readonly evaluation: Evaluation;
  /** Handle position − pointer position (world) at pointer-down: the handle does not jump. */
  readonly grabOffset: Vec2;
  readonly start: Vec2;
  last: Vec2;
  shift: boolean;
  moved: boolean;
  /** Patches not yet previewed (the next animation frame sends them) and their snap guide. */
  pending: NodePatch[] | null;
  pendingSnap: DragView['snap'];
  /** Every patch previewed so far, merged (what Escape has to put back). */
  touched: Map<string, Record<string, unknown>>;
  frame: number | null;
}

const localPoint = (el: Element, e: { clientX: number; clientY: number }): Vec2 => {
  const r = el.getBoundingClientRect();
  return [e.clientX - r.left, e.clientY - r.top];
};

export function useOverlayPointer(
  ref: RefObject<SVGSVGElement | null>,
  inputs: PointerInputs,
): OverlayPointer {
  const latest = useRef(inputs);
  latest.current = inputs;
  const [drag, setDrag] = useState<DragView | null>(null);
  const [hoverHandle, setHoverHandle] = useState<HandleItem | null>(null);

  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    let state: DragState | null = null;
    let reportedHover: string | null = null;

    const reportHover = (id: string | null) => {
      if (id === reportedHover) return;
      reportedHover = id;
      latest.current.onHoverNode(id);
    };

    /** Where the dragged handle goes for the pointer at css (snapped when Shift is held). */
    const place = (s: DragState, css: Vec2) => {
      const { screen } = latest.current;
      const p = toWorld(screen, css);
      const want: Vec2 = [p[0] + s.grabOffset[0], p[1] + s.grabOffset[1]];
      if (!s.shift) return { at: want, snap: null };
      const snapped = snapHandle(s.evaluation.scene.overlays, s.target, want, pxPerWorld(screen));
      return { at: snapped.at, snap: snapped };
    };

    const update = (s: DragState) => {
      const { at, snap } = place(s, s.last);
      s.pending = dragPatches(s.evaluation, s.target, at);
      s.pendingSnap = snap;
      for (const { nodeId, params } of s.pending)
        s.touched.set(nodeId, { ...s.touched.get(nodeId), ...params });
      if (s.frame === null) {
        s.frame = requestAnimationFrame(() => {
          s.frame = null;
          if (state !== s || !s.pending) return;
          latest.current.onPreview(s.pending);
          s.pending = null;
          setDrag({ target: s.target, snap: s.pendingSnap });
        });
      }
    };

    const end = (s: DragState) => {
      if (s.frame !== null) cancelAnimationFrame(s.frame);
      state = null;
      if (el.hasPointerCapture(s.pointerId)) el.releasePointerCapture(s.pointerId);
      setDrag(null);
    };

    /** Puts every previewed key back to its value before the drag; nothing is committed. */
    const cancel = (s: DragState) => {
      end(s);
      if (s.touched.size === 0) return;
      const touched = [...s.touched].map(([nodeId, params]) => ({ nodeId, params }));
      latest.current.onPreview(originalParams(s.evaluation, touched));
    };

    const onPointerDown = (e: PointerEvent) => {
      if (state) {
        // A second finger: this is a pinch, not a drag. Give the gesture to the pane.
        cancel(state);
        return;
      }
      // Only the first finger (or the main mouse button) grabs: a second finger means a pinch.
      if (!e.isPrimary || (e.pointerType === 'mouse' && e.button !== 0)) return;
      // Inspect mode and Alt-click explain the pixel under the pointer: they never grab a handle.
      if (latest.current.inspecting || e.altKey) return;
      const { handles, evaluation, screen } = latest.current;
      const css = localPoint(el, e);
      const i = hitHandle(
        handles.map((h) => h.at),
        css,
        OVERLAY_PX.handleHit,
      );
      if (i < 0) return;
      e.preventDefault();
      const target = handles[i].item;
      const p = toWorld(screen, css);
      state = {
        pointerId: e.pointerId,
        target,
        evaluation,
        grabOffset: [target.at[0] - p[0], target.at[1] - p[1]],
        start: css,
        last: css,
        shift: e.shiftKey,
        moved: false,
        pending: null,
        pendingSnap: null,
        touched: new Map(),
        frame: null,
      };
      el.setPointerCapture(e.pointerId);
      reportHover(target.nodeId);
      setHoverHandle(null);
      setDrag({ target, snap: null });
    };

    /** Hover: the handle under the pointer, else the nearest geometry within reach. */
    const hover = (css: Vec2) => {
      const { handles, items } = latest.current;
      const i = hitHandle(
        handles.map((h) => h.at),
        css,
        OVERLAY_PX.handleHit,
      );
      const handle = i >= 0 ? handles[i].item : null;
      setHoverHandle((old) =>
        old?.nodeId === handle?.nodeId && old?.handle === handle?.handle ? old : handle,
      );
      if (handle) return reportHover(handle.nodeId);
      const j = hitShape(
        items.map((it) => it.shape),
        css,
        OVERLAY_PX.geometryHit,
      );
      reportHover(j >= 0 ? items[j].nodeId : null);
    };

    const onPointerMove = (e: PointerEvent) => {
      const css = localPoint(el, e);
      if (state && e.pointerId === state.pointerId) {
        state.last = css;
        state.shift = e.shiftKey;
        if (css[0] !== state.start[0] || css[1] !== state.start[1]) state.moved = true;
        if (state.moved) update(state);
      } else if (!state && e.isPrimary && e.pointerType !== 'touch') hover(css);
    };

    const onPointerUp = (e: PointerEvent) => {
      const s = state;
      const css = localPoint(el, e);
      if (s && e.pointerId === s.pointerId) {
        s.last = css;
        s.shift = e.shiftKey;
        if (css[0] !== s.start[0] || css[1] !== s.start[1]) s.moved = true;
        end(s);
        if (s.moved) latest.current.onCommit(dragPatches(s.evaluation, s.target, place(s, s.last).at));
      }
      // What is under the pointer now (the drag moved things, or ended over something else).
      if (!state && e.isPrimary && e.pointerType !== 'touch') hover(css);
    };

    const onPointerCancel = (e: PointerEvent) => {
      if (state && e.pointerId === state.pointerId) cancel(state);
    };

    const onPointerLeave = () => {
      if (!state) {
        setHoverHandle(null);
        reportHover(null);
      }
    };

    const onKey = (e: KeyboardEvent) => {
      if (!state) return;
      if (e.key === 'Escape' && e.type === 'keydown') {
        e.preventDefault();
        e.stopPropagation();
        cancel(state);
      } else if (e.key === 'Shift' && state.moved) {
        state.shift = e.type === 'keydown';
        update(state);
      }
    };

    el.addEventListener('pointerdown', onPointerDown);
    el.addEventListener('pointermove', onPointerMove);
    el.addEventListener('pointerup', onPointerUp);
    el.addEventListener('pointercancel', onPointerCancel);
    el.addEventListener('pointerleave', onPointerLeave);
    window.addEventListener('keydown', onKey, true);
    window.addEventListener('keyup', onKey, true);
    return () => {
      if (state) cancel(state);
      el.removeEventListener('pointerdown', onPointerDown);
      el.removeEventListener('pointermove', onPointerMove);
      el.removeEventListener('pointerup', onPointerUp);
      el.removeEventListener('pointercancel', onPointerCancel);
      el.removeEventListener('pointerleave', onPointerLeave);
      window.removeEventListener('keydown', onKey, true);
      window.removeEventListener('keyup', onKey, true);
    };
  }, [ref]);

  return { drag, hoverHandle };
}
