/**
 * Hit testing in CSS pixels (pure): which handle a pointer grabs, which construction it hovers.
 * Handles win over geometry; within each, the nearest one wins (ties: the one drawn last, on top).
 */
import type { Vec2 } from '../../../nodes/core/values.ts';

/** Geometry as drawn, in CSS pixels. Lines are infinite (through a and b). */
export type ScreenShape =
  | { readonly shape: 'point'; readonly at: Vec2 }
  | { readonly shape: 'line'; readonly a: Vec2; readonly b: Vec2 }
  | { readonly shape: 'circle'; readonly c: Vec2; readonly r: number };

/**
 * Pixel distance from p to a shape: |p − at| for a point; |(p − a) × (b − a)| / |b − a| for the
 * infinite line; ||p − c| − r| for a circle's rim.
 */
export function distanceToShape(p: Vec2, s: ScreenShape): number {
  switch (s.shape) {
    case 'point':
      return Math.hypot(p[0] - s.at[0], p[1] - s.at[1]);
    case 'line': {
      const dx = s.b[0] - s.a[0];
      const dy = s.b[1] - s.a[1];
      const l = Math.hypot(dx, dy);
      if (l === 0) return Math.hypot(p[0] - s.a[0], p[1] - s.a[1]);
      return Math.abs((p[0] - s.a[0]) * dy - (p[1] - s.a[1]) * dx) / l;
    }
    case 'circle':
      return Math.abs(Math.hypot(p[0] - s.c[0], p[1] - s.c[1]) - s.r);
  }
}

/** Index of the nearest item within `radius` of p (distance from `distance`), or −1. */
function nearestWithin<T>(items: readonly T[], radius: number, distance: (item: T) => number): number {
  let best = -1;
  let bestDistance = radius;
  items.forEach((item, i) => {
    const d = distance(item);
    if (d <= bestDistance) {
      best = i;
      bestDistance = d;
    }
  });
  return best;
}

/** Index of the handle (centre in CSS px) nearest to p within `radius`, or −1. */
export function hitHandle(handles: readonly Vec2[], p: Vec2, radius: number): number {
  return nearestWithin(handles, radius, (h) => Math.hypot(p[0] - h[0], p[1] - h[1]));
}

/** Index of the shape nearest to p within `tolerance`, or −1. */
export function hitShape(shapes: readonly ScreenShape[], p: Vec2, tolerance: number): number {
  return nearestWithin(shapes, tolerance, (s) => distanceToShape(p, s));
}
