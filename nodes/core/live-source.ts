/**
 * Live sources (camera, video file) as picture keys. A program samples pictures by key (its
 * `pictures` list, one texture unit each); a live picture's key names the source, the crop aspect
 * and the fallback picture, so the browser can bind the live texture — or the fallback while the
 * source does not run — without anything else to look up. The key never enters the shader text,
 * so switching between a picture and a live source, or a new video frame, never recompiles.
 */
import type { TileSpec } from './tile-spec.ts';
import type { ImageRef, LiveRef } from './values.ts';

const PREFIX = 'live:';

/** The source a live picture reads: `webcam` (one camera for the page) or `video:<node id>`. */
export const liveSourceId = (live: LiveRef): string =>
  live.kind === 'webcam' ? 'webcam' : `video:${encodeURIComponent(live.nodeId)}`;

/** The key a program samples `image` by: its src, or for a live image `live:<source>|<w>|<h>|<fallback src>`. */
export function pictureKey(image: ImageRef): string {
  if (!image.live) return image.src;
  return `${PREFIX}${liveSourceId(image.live)}|${image.width}|${image.height}|${image.src}`;
}

export interface LiveKey {
  readonly source: string;
  /** The aspect the live frame is cropped to (that of the fallback picture): width / height. */
  readonly aspect: number;
  readonly fallback: string;
}

/** The parts of a live picture key, or null for a plain picture's src. */
export function parseLiveKey(key: string): LiveKey | null {
  if (!key.startsWith(PREFIX)) return null;
  const parts = key.slice(PREFIX.length).split('|', 3);
  if (parts.length < 3) return null;
  const [source, w, h] = parts;
  const fallback = key.slice(PREFIX.length + source.length + w.length + h.length + 3);
  const aspect = Number(w) / Number(h);
  return { source, aspect: Number.isFinite(aspect) && aspect > 0 ? aspect : 1, fallback };
}

/** Every picture a tile samples: its colouring's and its picture seeds'. */
export function tileImages(tile: TileSpec): ImageRef[] {
  const images = tile.coloring.mode === 'image' ? [tile.coloring.image] : [];
  for (const seed of tile.seeds ?? []) if (seed.kind === 'image') images.push(seed.image);
  return images;
}

/** The live sources a tile asks for (each node once). */
export function tileLiveSources(tile: TileSpec): LiveRef[] {
  const byNode = new Map<string, LiveRef>();
  for (const image of tileImages(tile)) if (image.live) byNode.set(image.live.nodeId, image.live);
  return [...byNode.values()];
}
