/**
 * The view: which part of the world plane the canvas shows. One home for its shape, its default,
 * and the pixel ↔ world mapping (docs/math.md "Plane, view") that the CPU raster, the overlay and
 * pan/zoom share (the GPU's twin is shader-gen/glsl/view.glsl.ts).
 */
import type { Vec2 } from './values.ts';

/** `center` is the world point at the middle of the canvas, `scale` the world height it shows. */
export interface View {
  readonly center: Vec2;
  readonly scale: number;
}

/** A new document's view: the origin in the middle, 4 world units high. */
export const DEFAULT_VIEW: View = { center: [0, 0], scale: 4 };

export const sameView = (a: View, b: View): boolean =>
  a.center[0] === b.center[0] && a.center[1] === b.center[1] && a.scale === b.scale;

/**
 * Pixel (px, py), origin bottom-left, sample offset (ox, oy) in [0,1)² (0.5, 0.5 = centre):
 * world = center + ((px + ox − W/2)/H, (py + oy − H/2)/H) · scale.
 */
export function pixelToWorld(
  view: View,
  width: number,
  height: number,
  px: number,
  py: number,
  ox = 0.5,
  oy = 0.5,
): Vec2 {
  return [
    view.center[0] + ((px + ox - width / 2) / height) * view.scale,
    view.center[1] + ((py + oy - height / 2) / height) * view.scale,
  ];
}

/** Inverse of pixelToWorld at the pixel corner: world → continuous pixel coordinates (origin bottom-left). */
export function worldToPixel(view: View, width: number, height: number, p: Vec2): Vec2 {
  return [
    ((p[0] - view.center[0]) / view.scale) * height + width / 2,
    ((p[1] - view.center[1]) / view.scale) * height + height / 2,
  ];
}

/**
 * The view of world height `scale` that keeps world point p at pixel (px, py) (origin
 * bottom-left, pixel corner): pixelToWorld solved for the centre,
 * center = p − ((px − W/2)/H, (py − H/2)/H) · scale.
 */
export function viewKeeping(
  p: Vec2,
  scale: number,
  width: number,
  height: number,
  px: number,
  py: number,
): View {
  return {
    center: [p[0] - ((px - width / 2) / height) * scale, p[1] - ((py - height / 2) / height) * scale],
    scale,
  };
}
