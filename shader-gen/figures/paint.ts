/**
 * Paints a figure layer (layer.ts) onto an 8-bit sRGB RGBA image (row 0 at the top, raster.ts's
 * layout): each stroke segment and dot covers a pixel by c = clamp(w/2 + ½ − d, 0, 1), d the
 * distance from the pixel centre to the segment (or dot centre minus radius), and blends
 * out = (1 − c)·out + c·colour. Labels are drawn with a single-stroke font (stroke-font.ts), placed as
 * the overlay and SVG place them. Shared by the CLI's PNG and the editor's PNG export.
 */
import type { View } from '../../nodes/core/scene.ts';
import type { Color, Vec2 } from '../../nodes/core/values.ts';
import { worldToPixel } from '../../nodes/core/view.ts';
import type { FigureLayer } from './layer.ts';
import { textStrokes } from './stroke-font.ts';

export interface PaintTarget {
  readonly width: number;
  readonly height: number;
  readonly data: Uint8ClampedArray;
}

/** Blends the colour in with coverage c; a transparent pixel (PNG export) becomes c opaque. */
function blend(img: PaintTarget, x: number, y: number, color: Color, c: number): void {
  if (c <= 0) return;
  const o = (y * img.width + x) * 4;
  for (let k = 0; k < 3; k++) img.data[o + k] = Math.round(img.data[o + k] * (1 - c) + color[k] * 255 * c);
  img.data[o + 3] = Math.max(img.data[o + 3], Math.round(255 * c));
}

/** Distance from (x, y) to the segment a–b. */
function segmentDistance(x: number, y: number, a: Vec2, b: Vec2): number {
  const ux = b[0] - a[0];
  const uy = b[1] - a[1];
  const l2 = ux * ux + uy * uy;
  const t = l2 > 0 ? Math.min(1, Math.max(0, ((x - a[0]) * ux + (y - a[1]) * uy) / l2)) : 0;
  return Math.hypot(x - a[0] - t * ux, y - a[1] - t * uy);
}

/** Calls f(x, y, cx, cy) for every pixel of the box [x0, x1] × [y0, y1] (top-down pixels) in the image. */
function eachPixel(
  img: PaintTarget,
  box: readonly number[],
  f: (x: number, y: number, cx: number, cy: number) => void,
) {
  const x0 = Math.max(0, Math.floor(box[0]));
  const x1 = Math.min(img.width - 1, Math.ceil(box[1]));
  const y0 = Math.max(0, Math.floor(box[2]));
  const y1 = Math.min(img.height - 1, Math.ceil(box[3]));
  for (let y = y0; y <= y1; y++) for (let x = x0; x <= x1; x++) f(x, y, x + 0.5, y + 0.5);
}

/**
 * One polyline in image pixels, `w` wide: one coverage per pixel over the whole polyline, so its
 * joints are not blended twice.
 */
function paintPolyline(img: PaintTarget, pts: readonly Vec2[], w: number, color: Color): void {
  const h = w / 2 + 1;
  const cover = new Map<number, number>();
  for (let i = 1; i < pts.length; i++) {
    const [a, b] = [pts[i - 1], pts[i]];
    const box = [
      Math.min(a[0], b[0]) - h,
      Math.max(a[0], b[0]) + h,
      Math.min(a[1], b[1]) - h,
      Math.max(a[1], b[1]) + h,
    ];
    eachPixel(img, box, (x, y, cx, cy) => {
      const c = Math.min(1, Math.max(0, w / 2 + 0.5 - segmentDistance(cx, cy, a, b)));
      const k = y * img.width + x;
      if (c > (cover.get(k) ?? 0)) cover.set(k, c);
    });
  }
  for (const [k, c] of cover) blend(img, k % img.width, Math.floor(k / img.width), color, c);
}

/** Labels as the overlay and SVG place them: 4 px right of and above the point, 14 px type. */
export const LABEL_OFFSET_PX = 4;
const LABEL_CAP_PX = 10;
const LABEL_STROKE_PX = 1.6;
const LABEL_OUTLINE_PX = 1.5;
const BLACK: Color = [0, 0, 0];

/** `pxScale` widens strokes and dots (an export larger than the live view keeps their look). */
export function paintFigures(img: PaintTarget, view: View, layer: FigureLayer, pxScale = 1): void {
  const toImage = (p: Vec2): Vec2 => {
    const [x, y] = worldToPixel(view, img.width, img.height, p);
    return [x, img.height - y];
  };
  for (const s of layer.strokes) paintPolyline(img, s.points.map(toImage), s.width * pxScale, s.color);
  for (const d of layer.dots) {
    const p = toImage(d.at);
    const r = d.r * pxScale;
    const h = r + 1;
    eachPixel(img, [p[0] - h, p[0] + h, p[1] - h, p[1] + h], (x, y, cx, cy) => {
      blend(img, x, y, d.color, Math.min(1, Math.max(0, r + 0.5 - Math.hypot(cx - p[0], cy - p[1]))));
    });
  }
  // Labels in the single-stroke font (stroke-font.ts), a dark outline under the colour so they read
  // on any picture, as the overlay's paint-order stroke does.
  for (const l of layer.labels) {
    const [x, y] = toImage(l.at);
    const off = LABEL_OFFSET_PX * pxScale;
    const lines = textStrokes(l.text, [x + off, y - off], LABEL_CAP_PX * pxScale);
    const w = LABEL_STROKE_PX * pxScale;
    for (const line of lines) paintPolyline(img, line, w + 2 * LABEL_OUTLINE_PX * pxScale, BLACK);
    for (const line of lines) paintPolyline(img, line, w, l.color);
  }
}
