/**
 * Pointer handling of the render overlay, 2D and 3D alike: hover (handles, then geometry) and
 * handle drags with pointer capture, Shift snapping, previews throttled to animation frames, one
 * commit on release and Escape to cancel. Listeners are native (not React's delegated ones) so that
 * `preventDefault()` on a grabbed handle is already set when the pointerdown bubbles to the
 * pan/zoom (or orbit) handler of the pane; every other event goes through untouched, so the view
 * pans and pinches. Where a pointer moves a handle to is the caller's (`grab`): the plane's
 * world mapping with snapping in 2D, the screen-parallel plane through the handle in 3D.
 */
import { type RefObject, useEffect, useRef, useState } from 'react';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { type HandleRef, type NodePatch, originalParams } from '../../../nodes/graph/drag-patches.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { OVERLAY_PX } from './constants.ts';
import { hitHandle } from './hit-test.ts';
import type { SnapGuide } from './snap-rules.ts';

/** A snap in effect: the guide drawn and where the handle snapped to (world). */
export type DragSnap = { readonly guide: SnapGuide; readonly at: Vec2 } | null;

/** Where the grabbed handle goes for the pointer at `css` (Shift held: `shift`), as params patches. */
export type DragPlacer = (css: Vec2, shift: boolean) => { patches: NodePatch[]; snap: DragSnap };

export interface PointerInputs<T extends HandleRef> {
  readonly evaluation: Evaluation;
  /** The handles as drawn: centre in CSS pixels and what they are. */
  readonly handles: readonly { readonly at: Vec2; readonly item: T }[];
  /** The node whose geometry is under `css` (within reach), or null. */
  readonly hoverGeometry: (css: Vec2) => string | null;
  /**
   * Pointer-down on `target` at `css`: the mapping of the pointer's later positions, fixed for the
   * drag (`evaluation` is the one at pointer-down, so previews never feed back).
   */
  readonly grab: (target: T, css: Vec2, evaluation: Evaluation) => DragPlacer;
  readonly onHoverNode: (id: string | null) => void;
  readonly onPreview: (patches: NodePatch[]) => void;
  readonly onCommit: (patches: NodePatch[]) => void;
  /** Inspect mode: no handle grabs (a click explains the pixel instead). */
  readonly inspecting?: boolean;
}

/** What the overlay draws about the drag in progress. */
export interface DragView<T extends HandleRef> {
  readonly target: T;
  readonly snap: DragSnap;
}

export interface OverlayPointer<T extends HandleRef> {
  readonly drag: DragView<T> | null;
  /** The handle under the pointer (grab cursor, bigger handle), when not dragging. */
  readonly hoverHandle: T | null;
}

interface DragState<T extends HandleRef> {
  readonly pointerId: number;
  readonly target: T;
  /** Evaluation at pointer-down (what Escape puts back is read from it). */
  readonly evaluation: Evaluation;
  readonly place: DragPlacer;
  readonly start: Vec2;
  last: Vec2;
  shift: boolean;
  moved: boolean;
  /** Patches not yet previewed (the next animation frame sends them) and their snap guide. */
  pending: NodePatch[] | null;
  pendingSnap: DragSnap;
  /** Every patch previewed so far, merged (what Escape has to put back). */
  touched: Map<string, Record<string, unknown>>;
  frame: number | null;
}

const localPoint = (el: Element, e: { clientX: number; clientY: number }): Vec2 => {
  const r = el.getBoundingClientRect();
  return [e.clientX - r.left, e.clientY - r.top];
};

export function useOverlayPointer<T extends HandleRef>(
  ref: RefObject<SVGSVGElement | null>,
  inputs: PointerInputs<T>,
): OverlayPointer<T> {
  const latest = useRef(inputs);
  latest.current = inputs;
  const [drag, setDrag] = useState<DragView<T> | null>(null);
  const [hoverHandle, setHoverHandle] = useState<T | null>(null);

  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    let state: DragState<T> | null = null;
    let reportedHover: string | null = null;

    const reportHover = (id: string | null) => {
      if (id === reportedHover) return;
      reportedHover = id;
      latest.current.onHoverNode(id);
    };

    const update = (s: DragState<T>) => {
      const { patches, snap } = s.place(s.last, s.shift);
      s.pending = patches;
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

    const end = (s: DragState<T>) => {
      if (s.frame !== null) cancelAnimationFrame(s.frame);
      state = null;
      if (el.hasPointerCapture(s.pointerId)) el.releasePointerCapture(s.pointerId);
      setDrag(null);
    };

    /** Puts every previewed key back to its value before the drag; nothing is committed. */
    const cancel = (s: DragState<T>) => {
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
      const { handles, evaluation, grab } = latest.current;
      const css = localPoint(el, e);
      const i = hitHandle(
        handles.map((h) => h.at),
        css,
        OVERLAY_PX.handleHit,
      );
      if (i < 0) return;
      e.preventDefault();
      const target = handles[i].item;
      state = {
        pointerId: e.pointerId,
        target,
        evaluation,
        place: grab(target, css, evaluation),
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
      const { handles, hoverGeometry } = latest.current;
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
      reportHover(hoverGeometry(css));
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
        if (s.moved) latest.current.onCommit(s.place(s.last, s.shift).patches);
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
