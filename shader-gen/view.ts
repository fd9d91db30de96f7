/**
 * Pixel ↔ world mapping (docs/math.md "Plane, view") and the sub-pixel sample pattern shared by the CPU
 * raster and the GPU's progressive accumulation.
 */
import type { View } from '../nodes/core/scene.ts';
import type { Vec2 } from '../nodes/core/values.ts';

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

/** R2 low-discrepancy sequence (plastic constant): g = 1.32471795724…, α = (1/g, 1/g²). */
const R2 = [0.7548776662466927, 0.5698402909980532] as const;

/** Offset of sample k inside a pixel: k = 0 is the centre; k > 0 follows the R2 sequence. */
export function sampleOffset(k: number): Vec2 {
  if (k === 0) return [0.5, 0.5];
  return [(0.5 + k * R2[0]) % 1, (0.5 + k * R2[1]) % 1];
}
