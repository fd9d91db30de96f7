/**
 * The 3D view's pointer controls, the twin of pan-zoom.ts: drag to orbit about the target, right-
 * drag (or Shift-drag, or the middle button) to pan, wheel to zoom about the cursor; on touch one
 * finger orbits and two fingers pinch (zoom about their midpoint) and pan with it. Each move is
 * computed from the camera at the gesture's start (camera-3d.ts), so nothing drifts. Events whose
 * default was prevented (the overlay claims handle drags that way) are left alone.
 */
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import { orbit, type PaneSize, pan, zoomAbout } from './camera-3d.ts';

/** Radians of orbit per pixel of drag: a drag across the pane's height turns half a turn. */
const orbitPerPixel = (pane: PaneSize) => Math.PI / Math.max(1, pane.height);
/** Zoom factor per wheel pixel (the same feel as the 2D view's wheel). */
const WHEEL_ZOOM_PER_PIXEL = 0.0015;
const WHEEL_LINE_PX = 16;

type Mode = 'orbit' | 'pan';

/**
 * Drag right: the camera swings left about the target (the object turns with the pointer);
 * drag down: the camera rises (looks more from above).
 */
export const orbitDrag = (start: Camera3d, pane: PaneSize, dx: number, dy: number): Camera3d =>
  orbit(start, -dx * orbitPerPixel(pane), dy * orbitPerPixel(pane));

/**
 * Two fingers from (mid0, distance0) to (mid, distance): pan by the midpoint's move, then zoom
 * about the new midpoint by distance0/distance, so the point first under the midpoint stays under it.
 */
export function pinch(
  start: Camera3d,
  pane: PaneSize,
  mid0: Vec2,
  distance0: number,
  mid: Vec2,
  distance: number,
): Camera3d {
  const moved = pan(start, pane, mid[0] - mid0[0], mid[1] - mid0[1]);
  const ratio = distance > 0 && distance0 > 0 ? distance0 / distance : 1;
  return zoomAbout(moved, pane, mid[0], mid[1], ratio);
}

export function attachOrbitControls(
  el: HTMLElement,
  get: () => Camera3d,
  set: (c: Camera3d) => void,
): () => void {
  const size = (): PaneSize => ({ width: el.clientWidth || 1, height: el.clientHeight || 1 });
  const local = (e: { clientX: number; clientY: number }): Vec2 => {
    const r = el.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  const pointers = new Map<number, Vec2>();
  let gesture: { camera: Camera3d; mode: Mode; mid: Vec2; distance: number } | null = null;

  const midpoint = (): { mid: Vec2; distance: number } => {
    const pts = [...pointers.values()];
    if (pts.length < 2) return { mid: pts[0], distance: 0 };
    return {
      mid: [(pts[0][0] + pts[1][0]) / 2, (pts[0][1] + pts[1][1]) / 2],
      distance: Math.hypot(pts[0][0] - pts[1][0], pts[0][1] - pts[1][1]),
    };
  };
  const startGesture = (mode: Mode) => {
    if (pointers.size === 0) {
      gesture = null;
      return;
    }
    gesture = { camera: get(), mode, ...midpoint() };
  };

  const onDown = (e: PointerEvent) => {
    if (e.defaultPrevented || pointers.size >= 2) return;
    const mouse = e.pointerType === 'mouse';
    if (mouse && e.button > 2) return;
    pointers.set(e.pointerId, local(e));
    try {
      el.setPointerCapture(e.pointerId);
    } catch {
      // not an active pointer (synthetic events): the gesture works without the capture
    }
    const panning = mouse && (e.button === 1 || e.button === 2 || e.shiftKey);
    startGesture(panning ? 'pan' : 'orbit');
  };

  const onMove = (e: PointerEvent) => {
    if (!pointers.has(e.pointerId) || !gesture) return;
    pointers.set(e.pointerId, local(e));
    const pane = size();
    const { mid, distance } = midpoint();
    const dx = mid[0] - gesture.mid[0];
    const dy = mid[1] - gesture.mid[1];
    if (pointers.size >= 2) set(pinch(gesture.camera, pane, gesture.mid, gesture.distance, mid, distance));
    else if (gesture.mode === 'pan') set(pan(gesture.camera, pane, dx, dy));
    else set(orbitDrag(gesture.camera, pane, dx, dy));
  };

  const onUp = (e: PointerEvent) => {
    if (!pointers.delete(e.pointerId)) return;
    if (el.hasPointerCapture(e.pointerId)) el.releasePointerCapture(e.pointerId);
    // The finger left on the pane goes on orbiting from where things are now.
    startGesture(gesture?.mode === 'pan' ? 'pan' : 'orbit');
  };

  const onWheel = (e: WheelEvent) => {
    if (e.defaultPrevented) return;
    e.preventDefault();
    const pane = size();
    const unit = e.deltaMode === 1 ? WHEEL_LINE_PX : e.deltaMode === 2 ? pane.height : 1;
    // Trackpad pinch arrives as a ctrl+wheel with small deltas: make it as responsive as a wheel.
    const dy = e.deltaY * unit * (e.ctrlKey ? 5 : 1);
    const [x, y] = local(e);
    set(zoomAbout(get(), pane, x, y, Math.exp(dy * WHEEL_ZOOM_PER_PIXEL)));
    if (gesture) startGesture(gesture.mode);
  };

  // Right-drag pans: the context menu would interrupt it.
  const onContextMenu = (e: MouseEvent) => e.preventDefault();

  el.addEventListener('pointerdown', onDown);
  el.addEventListener('pointermove', onMove);
  el.addEventListener('pointerup', onUp);
  el.addEventListener('pointercancel', onUp);
  el.addEventListener('wheel', onWheel, { passive: false });
  el.addEventListener('contextmenu', onContextMenu);
  const touchAction = el.style.touchAction;
  el.style.touchAction = 'none';
  return () => {
    el.removeEventListener('pointerdown', onDown);
    el.removeEventListener('pointermove', onMove);
    el.removeEventListener('pointerup', onUp);
    el.removeEventListener('pointercancel', onUp);
    el.removeEventListener('wheel', onWheel);
    el.removeEventListener('contextmenu', onContextMenu);
    el.style.touchAction = touchAction;
    pointers.clear();
  };
}
