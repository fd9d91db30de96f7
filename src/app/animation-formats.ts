/**
 * The formats "Export animation…" can write, their file names and MIME types: light enough for the
 * dialog to import at once (the encoders themselves, animation-encoders.ts, load on demand).
 */
import type { VideoCodec } from 'mediabunny';

export const ANIMATION_FORMATS = {
  'webm-vp9': { label: 'WebM (VP9)', extension: 'webm', mime: 'video/webm', codec: 'vp9' },
  'webm-vp8': { label: 'WebM (VP8)', extension: 'webm', mime: 'video/webm', codec: 'vp8' },
  'mp4-avc': { label: 'MP4 (H.264)', extension: 'mp4', mime: 'video/mp4', codec: 'avc' },
  gif: { label: 'GIF (256 colours per frame)', extension: 'gif', mime: 'image/gif', codec: null },
} as const satisfies Record<
  string,
  { label: string; extension: string; mime: string; codec: VideoCodec | null }
>;

export type AnimationFormat = keyof typeof ANIMATION_FORMATS;

export interface FrameSize {
  readonly width: number;
  readonly height: number;
  readonly fps: number;
}

/** Video encoders want even sides (4:2:0 chroma is subsampled 2×2): the nearest even size below. */
export const evenSize = (n: number): number => Math.max(2, n - (n % 2));
