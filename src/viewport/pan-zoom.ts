/**
 * Pan and zoom of a View with pointer events: drag to pan, wheel to zoom about the cursor, two
 * fingers to pinch (zoom about their midpoint and pan with it). Events whose default was prevented
 * (the overlay claims handle drags that way) are left alone.
 *
 * A CSS pixel (x right, y down, relative to the element) maps to the world point
 *   center + ((x − W/2)/H, (H/2 − y)/H) · scale      (docs/math.md "Plane, view", y up),
 * so keeping the world point under the cursor fixed while the scale changes from s to s' gives
 *   center' = p − ((x − W/2)/H, (H/2 − y)/H) · s'.
 */
import type { Vec2 } from '../../nodes/core/values.ts';
import { viewKeeping as keepAtPixel, pixelToWorld, type View } from '../../nodes/core/view.ts';

/** Zoom factor per wheel pixel: 100 px of wheel (one notch, about) zooms by e^0.15 ≈ 1.16. */
const WHEEL_ZOOM_PER_PIXEL = 0.0015;
/** Lines and pages of wheel delta in pixels. */
const WHEEL_LINE_PX = 16;

/** View scales outside this range break float32 precision or show nothing. */
const MIN_SCALE = 1e-6;
const MAX_SCALE = 1e6;

export interface PanZoomOptions {
  /** Height of the canvas in CSS pixels (default: the element's clientHeight). */
  canvasHeightPx?: () => number;
}

/** World point under the element-relative CSS pixel (x, y): pixel (x, h − y) from the bottom-left. */
function worldAt(view: View, w: number, h: number, x: number, y: number): Vec2 {
  return pixelToWorld(view, w, h, x, h - y, 0, 0);
}

/** The view with scale `scale` (clamped) that keeps world point `p` at CSS pixel (x, y). */
function viewKeeping(p: Vec2, scale: number, w: number, h: number, x: number, y: number): View {
  return keepAtPixel(p, Math.min(MAX_SCALE, Math.max(MIN_SCALE, scale)), w, h, x, h - y);
}

export function attachPanZoom(
  el: HTMLElement,
  get: () => View,
  set: (v: View) => void,
  opts: PanZoomOptions = {},
): () => void {
  const height = () => opts.canvasHeightPx?.() || el.clientHeight || 1;
  const width = () => el.clientWidth || 1;
  const local = (e: { clientX: number; clientY: number }): Vec2 => {
    const r = el.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  /** Pointers down on the element, at their last positions. */
  const pointers = new Map<number, Vec2>();
  /** The gesture's start: view and (for two pointers) the world point under their midpoint and their distance. */
  let gesture: { view: View; anchor: Vec2; distance: number } | null = null;

  const startGesture = () => {
    const pts = [...pointers.values()];
    const view = get();
    if (pts.length === 0) {
      gesture = null;
      return;
    }
    const mid: Vec2 = pts.length === 1 ? pts[0] : [(pts[0][0] + pts[1][0]) / 2, (pts[0][1] + pts[1][1]) / 2];
    const distance = pts.length >= 2 ? Math.hypot(pts[0][0] - pts[1][0], pts[0][1] - pts[1][1]) : 0;
    gesture = { view, anchor: worldAt(view, width(), height(), mid[0], mid[1]), distance };
  };

  const onDown = (e: PointerEvent) => {
    if (e.defaultPrevented || (e.pointerType === 'mouse' && e.button !== 0)) return;
    if (pointers.size >= 2) return;
    pointers.set(e.pointerId, local(e));
    try {
      el.setPointerCapture(e.pointerId); // keep panning when the pointer leaves the element
    } catch {
      // not an active pointer (synthetic events): panning works without the capture
    }
    startGesture();
  };

  const onMove = (e: PointerEvent) => {
    if (!pointers.has(e.pointerId) || !gesture) return;
    pointers.set(e.pointerId, local(e));
    const pts = [...pointers.values()];
    const w = width();
    const h = height();
    if (pts.length === 1) {
      set(viewKeeping(gesture.anchor, gesture.view.scale, w, h, pts[0][0], pts[0][1]));
    } else {
      const mid: Vec2 = [(pts[0][0] + pts[1][0]) / 2, (pts[0][1] + pts[1][1]) / 2];
      const distance = Math.hypot(pts[0][0] - pts[1][0], pts[0][1] - pts[1][1]);
      const ratio = distance > 0 && gesture.distance > 0 ? gesture.distance / distance : 1;
      set(viewKeeping(gesture.anchor, gesture.view.scale * ratio, w, h, mid[0], mid[1]));
    }
  };

  const onUp = (e: PointerEvent) => {
    if (!pointers.delete(e.pointerId)) return;
    if (el.hasPointerCapture(e.pointerId)) el.releasePointerCapture(e.pointerId);
    startGesture(); // the remaining finger continues the pan from where it is
  };

  const onWheel = (e: WheelEvent) => {
    if (e.defaultPrevented) return;
    e.preventDefault();
    const unit = e.deltaMode === 1 ? WHEEL_LINE_PX : e.deltaMode === 2 ? height() : 1;
    // Trackpad pinch arrives as a ctrl+wheel with small deltas: make it as responsive as a wheel.
    const dy = e.deltaY * unit * (e.ctrlKey ? 5 : 1);
    const [x, y] = local(e);
    const view = get();
    const w = width();
    const h = height();
    set(viewKeeping(worldAt(view, w, h, x, y), view.scale * Math.exp(dy * WHEEL_ZOOM_PER_PIXEL), w, h, x, y));
    if (gesture) startGesture();
  };

  el.addEventListener('pointerdown', onDown);
  el.addEventListener('pointermove', onMove);
  el.addEventListener('pointerup', onUp);
  el.addEventListener('pointercancel', onUp);
  el.addEventListener('wheel', onWheel, { passive: false });
  // Pinch needs the browser not to scroll or zoom the page under two fingers.
  const touchAction = el.style.touchAction;
  el.style.touchAction = 'none';
  return () => {
    el.removeEventListener('pointerdown', onDown);
    el.removeEventListener('pointermove', onMove);
    el.removeEventListener('pointerup', onUp);
    el.removeEventListener('pointercancel', onUp);
    el.removeEventListener('wheel', onWheel);
    el.style.touchAction = touchAction;
    pointers.clear();
  };
}
