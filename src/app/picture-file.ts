/**
 * A picture file chosen for the image node, made into what the node keeps: a data:image URL with
 * its pixel size. A PNG, JPEG, WebP or GIF that fits the limits (LIMITS.maxPictureSide on each
 * side, LIMITS.maxImageDataUrlChars of data) is kept byte for byte; anything else — a 6000-pixel
 * photo, an SVG, a 20 MB file — is redrawn at the largest size that fits, so choosing a phone
 * photo just works instead of ending in "picture too big".
 */
import { LIMITS } from '../../nodes/core/limits.ts';

export interface PictureData {
  readonly src: string;
  readonly width: number;
  readonly height: number;
}

/** Types kept as they are (the texture loader decodes them with createImageBitmap). */
const KEPT_AS_IS = new Set(['image/png', 'image/jpeg', 'image/webp', 'image/gif']);

/**
 * The size (w', h') = round(s·w, s·h) with s = min(1, side / max(w, h)): the picture shrunk, aspect
 * kept, until its longer side is at most `side` (never below 1 pixel).
 */
export function fitPictureSize(
  width: number,
  height: number,
  side: number,
): { width: number; height: number } {
  const s = Math.min(1, side / Math.max(width, height));
  return { width: Math.max(1, Math.round(width * s)), height: Math.max(1, Math.round(height * s)) };
}

/** Base64 data URL length for a file of `bytes` bytes (4 characters per 3 bytes, plus the header). */
const dataUrlChars = (bytes: number, type: string) =>
  Math.ceil(bytes / 3) * 4 + `data:${type};base64,`.length;

export function readDataUrl(file: Blob): Promise<string> {
  return new Promise((resolve, reject) => {
    const reader = new FileReader();
    reader.onload = () => resolve(String(reader.result));
    reader.onerror = () => reject(reader.error ?? new Error('the file could not be read'));
    reader.readAsDataURL(file);
  });
}

function decode(url: string): Promise<HTMLImageElement> {
  return new Promise((resolve, reject) => {
    const img = new Image();
    img.onload = () => resolve(img);
    img.onerror = () => reject(new Error('the browser cannot read it as a picture'));
    img.src = url;
  });
}

/** The file as the image node keeps it; rejects with a sentence a user can act on. */
export async function pictureFromFile(file: File): Promise<PictureData> {
  if (!file.type.startsWith('image/'))
    throw new Error(`“${file.name}” is not a picture (${file.type || 'unknown type'})`);
  const url = URL.createObjectURL(file);
  try {
    const img = await decode(url);
    const width = img.naturalWidth;
    const height = img.naturalHeight;
    if (!(width > 0 && height > 0)) throw new Error(`“${file.name}” has no pixel size`);
    const side = LIMITS.maxPictureSide;
    const fits =
      width <= side && height <= side && dataUrlChars(file.size, file.type) <= LIMITS.maxImageDataUrlChars;
    if (fits && KEPT_AS_IS.has(file.type)) return { src: await readDataUrl(file), width, height };
    // Redraw: PNG keeps transparency and sharp edges; a photo that is still too big as PNG goes
    // to JPEG, then smaller, until it fits.
    let size = fitPictureSize(width, height, side);
    for (let attempt = 0; attempt < 8; attempt++) {
      const canvas = document.createElement('canvas');
      canvas.width = size.width;
      canvas.height = size.height;
      canvas.getContext('2d')!.drawImage(img, 0, 0, size.width, size.height);
      for (const [type, quality] of [
        ['image/png', undefined],
        ['image/jpeg', 0.9],
      ] as const) {
        const src = canvas.toDataURL(type, quality);
        if (src.length <= LIMITS.maxImageDataUrlChars) return { src, ...size };
      }
      size = fitPictureSize(size.width, size.height, Math.floor(Math.max(size.width, size.height) * 0.75));
    }
    throw new Error(`“${file.name}” could not be made small enough to keep`);
  } finally {
    URL.revokeObjectURL(url);
  }
}
