/**
 * The formats an animation can be written in (the editor's "Export animation…" and `kleinflow
 * render --frames`), their file names and MIME types: light enough for the dialog and the CLI to
 * import at once (the encoders themselves, animation-sink.ts, load on demand).
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
/** The formats a codec encodes (the rest, GIF, needs none). */
export type VideoFormat = Exclude<AnimationFormat, 'gif'>;

export interface FrameSize {
  readonly width: number;
  readonly height: number;
  readonly fps: number;
}

/** Takes the frames in order (RGBA, row 0 at the top) and makes the file. */
export interface FrameSink {
  /** Frame `index` of the file (0 = the file's first frame), shown from index/fps for 1/fps. */
  add(pixels: Uint8Array | Uint8ClampedArray, index: number): Promise<void>;
  finish(): Promise<Uint8Array>;
  cancel(): Promise<void>;
}

/** Video encoders want even sides (4:2:0 chroma is subsampled 2×2): the nearest even size below. */
export const evenSize = (n: number): number => Math.max(2, n - (n % 2));

/** Whether a format is a video (encoded by a codec, so its sides must be even). */
export const isVideoFormat = (format: AnimationFormat): format is VideoFormat => format !== 'gif';

/**
 * The file format a path asks for by its extension — .webm is VP9 (smaller than VP8 at the same
 * quality), .mp4 H.264, .gif a GIF — or undefined for any other path (the CLI's folder of PNGs).
 */
export function animationFormatOfPath(path: string): AnimationFormat | undefined {
  const extension = /\.([a-z0-9]+)$/i.exec(path)?.[1]?.toLowerCase();
  return extension ? FORMAT_OF_EXTENSION[extension] : undefined;
}

const FORMAT_OF_EXTENSION: Readonly<Record<string, AnimationFormat>> = {
  webm: 'webm-vp9',
  mp4: 'mp4-avc',
  gif: 'gif',
};
