/**
 * Click to place (a handle's `placeOnClick`, e.g. the Maskit slice's μ): a press on empty space
 * that is released within OVERLAY_PX.clickSlop of where it started moves that handle to the press
 * point, one commit (one undo step). The press is left to the pane as it is — a drag still pans, and
 * a pan that moved no further than the slop kept the world point under the pointer anyway. The
 * listener on the overlay runs after use-overlay-pointer's (registered later), so a press that
 * grabbed a handle is already `defaultPrevented` and is not a click here; the release and the moves
 * are watched on the window, since the pane captures the pointer while it pans.
 */
import { type RefObject, useEffect, useRef } from 'react';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { NodePatch } from '../../../nodes/graph/drag-patches.ts';
import { OVERLAY_PX } from './constants.ts';

export interface ClickToPlace {
  /** The patches that put the placeable handle at CSS point `css`; null: nothing to place. */
  readonly place: ((css: Vec2) => NodePatch[]) | null;
  readonly onCommit: (patches: NodePatch[]) => void;
  /** Inspect mode: a click explains the pixel instead. */
  readonly inspecting: boolean;
}

interface PendingClick {
  readonly pointerId: number;
  readonly client: Vec2;
  readonly patches: NodePatch[];
}

export function useClickToPlace(ref: RefObject<SVGSVGElement | null>, inputs: ClickToPlace): void {
  const latest = useRef(inputs);
  latest.current = inputs;

  useEffect(() => {
    const el = ref.current;
    if (!el) return;
    let pending: PendingClick | null = null;
    const moved = (e: PointerEvent, p: PendingClick) =>
      Math.hypot(e.clientX - p.client[0], e.clientY - p.client[1]) > OVERLAY_PX.clickSlop;

    const onDown = (e: PointerEvent) => {
      pending = null; // a second finger makes it a pinch
      const { place, inspecting } = latest.current;
      if (!place || inspecting || e.altKey || e.defaultPrevented || !e.isPrimary) return;
      if (e.pointerType === 'mouse' && e.button !== 0) return;
      const r = el.getBoundingClientRect();
      const patches = place([e.clientX - r.left, e.clientY - r.top]);
      pending = { pointerId: e.pointerId, client: [e.clientX, e.clientY], patches };
    };
    const onMove = (e: PointerEvent) => {
      if (pending?.pointerId === e.pointerId && moved(e, pending)) pending = null;
    };
    const onUp = (e: PointerEvent) => {
      const p = pending;
      if (p?.pointerId !== e.pointerId) return;
      pending = null;
      if (!moved(e, p)) latest.current.onCommit(p.patches);
    };
    const onCancel = () => {
      pending = null;
    };

    el.addEventListener('pointerdown', onDown);
    window.addEventListener('pointermove', onMove, true);
    window.addEventListener('pointerup', onUp, true);
    window.addEventListener('pointercancel', onCancel, true);
    return () => {
      el.removeEventListener('pointerdown', onDown);
      window.removeEventListener('pointermove', onMove, true);
      window.removeEventListener('pointerup', onUp, true);
      window.removeEventListener('pointercancel', onCancel, true);
    };
  }, [ref]);
}
