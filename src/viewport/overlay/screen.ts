/**
 * World ↔ CSS-pixel mapping of the render pane (origin top-left, y down), built on the renderer's
 * pixelToWorld / worldToPixel (origin bottom-left) so the overlay and the picture always agree.
 */
import type { HandleItem, OverlayItem, View } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { pixelToWorld, worldToPixel } from '../../../nodes/core/view.ts';
import type { ScreenShape } from './hit-test.ts';

export interface Screen {
  readonly view: View;
  readonly width: number;
  readonly height: number;
}

/** World point → CSS pixel: (px, H − py) with (px, py) = worldToPixel(p). */
export function toCss(s: Screen, p: Vec2): Vec2 {
  const [x, y] = worldToPixel(s.view, s.width, s.height, p);
  return [x, s.height - y];
}

/** CSS pixel → world point (the exact inverse of toCss). */
export function toWorld(s: Screen, css: Vec2): Vec2 {
  return pixelToWorld(s.view, s.width, s.height, css[0], s.height - css[1], 0, 0);
}

/** CSS pixels per world unit: H / scale (the view's scale is the world height of the pane). */
export function pxPerWorld(s: Screen): number {
  return s.height / s.view.scale;
}

/**
 * The part of p(t) = a + t(b − a), t in [tMin, tMax], inside the rectangle [−m, W+m] × [−m, H+m]
 * (CSS px), or null when it misses it. Parametric clipping (Liang–Barsky): each slab bound narrows
 * [t0, t1].
 */
function clipParametric(
  a: Vec2,
  b: Vec2,
  width: number,
  height: number,
  margin: number,
  tMin: number,
  tMax: number,
): [Vec2, Vec2] | null {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  if (dx === 0 && dy === 0) return null;
  let t0 = tMin;
  let t1 = tMax;
  const slabs: [number, number, number, number][] = [
    [a[0], dx, -margin, width + margin],
    [a[1], dy, -margin, height + margin],
  ];
  for (const [p, d, lo, hi] of slabs) {
    if (d === 0) {
      if (p < lo || p > hi) return null;
      continue;
    }
    const ta = (lo - p) / d;
    const tb = (hi - p) / d;
    t0 = Math.max(t0, Math.min(ta, tb));
    t1 = Math.min(t1, Math.max(ta, tb));
  }
  if (!(t0 <= t1)) return null;
  return [
    [a[0] + t0 * dx, a[1] + t0 * dy],
    [a[0] + t1 * dx, a[1] + t1 * dy],
  ];
}

/** The part of the infinite line through a and b (CSS px) inside the rectangle grown by `margin`. */
export const clipLineToRect = (a: Vec2, b: Vec2, width: number, height: number, margin: number) =>
  clipParametric(a, b, width, height, margin, -Infinity, Infinity);

/** The part of the segment a–b (CSS px) inside the rectangle grown by `margin` (the orbit's path). */
export const clipSegmentToRect = (a: Vec2, b: Vec2, width: number, height: number, margin: number) =>
  clipParametric(a, b, width, height, margin, 0, 1);

/**
 * Whether a circle's rim (centre c, radius r, CSS px) crosses the rectangle grown by `margin`:
 * the rim meets it iff (distance from c to the rectangle) ≤ r ≤ (distance to its farthest corner).
 */
export function circleRimVisible(c: Vec2, r: number, width: number, height: number, margin: number): boolean {
  const lo = -margin;
  const hiX = width + margin;
  const hiY = height + margin;
  const nx = Math.min(Math.max(c[0], lo), hiX);
  const ny = Math.min(Math.max(c[1], lo), hiY);
  const near = Math.hypot(c[0] - nx, c[1] - ny);
  const far = Math.hypot(Math.max(c[0] - lo, hiX - c[0]), Math.max(c[1] - lo, hiY - c[1]));
  return near <= r && r <= far;
}

/** An overlay item placed in CSS pixels. */
export interface ScreenItem {
  readonly nodeId: string;
  readonly color: string;
  readonly label?: string;
  readonly shape: ScreenShape;
}

/** A handle placed in CSS pixels, with its world position and its node's colour. */
export interface ScreenHandle {
  readonly item: HandleItem;
  readonly at: Vec2;
  readonly color: string;
}

/** The scene's overlays in CSS pixels (a line keeps two of its points; it is drawn infinite). */
export function placeOverlays(overlays: readonly OverlayItem[], s: Screen): ScreenItem[] {
  return overlays.map(({ nodeId, color, label, shape }) => {
    const placed: ScreenShape =
      shape.shape === 'point'
        ? { shape: 'point', at: toCss(s, shape.at) }
        : shape.shape === 'line'
          ? { shape: 'line', a: toCss(s, shape.line.a), b: toCss(s, shape.line.b) }
          : { shape: 'circle', c: toCss(s, shape.circle.c), r: shape.circle.r * pxPerWorld(s) };
    return { nodeId, color, ...(label ? { label } : {}), shape: placed };
  });
}

/**
 * The scene's handles in CSS pixels, coloured like their node. Where handles coincide (a line's
 * end wired from a point offers a handle on top of the point's own) only the first, most upstream
 * one is kept: it is the one the user means, and dragging either moves the same point.
 */
export function placeHandles(
  handles: readonly HandleItem[],
  colorOf: (nodeId: string) => string,
  s: Screen,
): ScreenHandle[] {
  const placed: ScreenHandle[] = [];
  for (const item of handles) {
    const at = toCss(s, item.at);
    if (placed.some((h) => Math.abs(h.at[0] - at[0]) < 0.5 && Math.abs(h.at[1] - at[1]) < 0.5)) continue;
    placed.push({ item, at, color: colorOf(item.nodeId) });
  }
  return placed;
}
