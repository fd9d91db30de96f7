/**
 * The Recent list's small picture of a document: the live render as shown now (Viewport.snapshot,
 * which reads the accumulated picture back; the WebGL canvas itself keeps no drawing buffer to
 * copy), scaled into a square PNG data URL of a few kilobytes.
 */
import type { Viewport } from '../../viewport/viewport.ts';

export const THUMBNAIL_PX = 96;

/** The thumbnail, or undefined before the first frame or where 2D canvases are unavailable. */
export function renderThumbnail(viewport: Viewport | null): string | undefined {
  const canvas = document.querySelector<HTMLCanvasElement>('.kf-render__canvas');
  // The snapshot has the drawing buffer's size; getContext returns the viewport's own context.
  const gl = canvas?.getContext('webgl2');
  const pixels = viewport?.snapshot();
  if (!gl || !pixels) return undefined;
  const w = gl.drawingBufferWidth;
  const h = gl.drawingBufferHeight;
  if (w * h * 4 !== pixels.length || w === 0 || h === 0) return undefined;
  const full = document.createElement('canvas');
  full.width = w;
  full.height = h;
  const thumb = document.createElement('canvas');
  thumb.width = THUMBNAIL_PX;
  thumb.height = THUMBNAIL_PX;
  const fullCtx = full.getContext('2d');
  const thumbCtx = thumb.getContext('2d');
  if (!fullCtx || !thumbCtx) return undefined;
  fullCtx.putImageData(new ImageData(new Uint8ClampedArray(pixels), w, h), 0, 0);
  // The centred square of the picture, as the gallery's thumbnails show.
  const side = Math.min(w, h);
  thumbCtx.drawImage(full, (w - side) / 2, (h - side) / 2, side, side, 0, 0, THUMBNAIL_PX, THUMBNAIL_PX);
  return thumb.toDataURL('image/png');
}
