/**
 * Which video formats "Export animation…" can offer in this browser. The codecs a browser has vary
 * (headless Chromium builds often lack H.264): `supportedFormats` asks the encoder itself
 * (VideoEncoder.isConfigSupported, through mediabunny's canEncodeVideo) before the dialog offers a
 * format. The files themselves are written by src/io/animation-sink.ts, which the CLI shares.
 * Loaded on demand (import()), so mediabunny stays out of the editor's start-up bundle.
 */
import { canEncodeVideo } from 'mediabunny';
import {
  ANIMATION_FORMATS,
  type AnimationFormat,
  evenSize,
  type FrameSize,
} from '../io/animation-formats.ts';
import { VIDEO_QUALITY } from '../io/video-sink.ts';

/** Which formats this browser can write at this size (GIF always; videos when WebCodecs says so). */
export async function supportedFormats(size: FrameSize): Promise<Record<AnimationFormat, boolean>> {
  const result = { 'webm-vp9': false, 'webm-vp8': false, 'mp4-avc': false, gif: true };
  if (typeof VideoEncoder === 'undefined') return result;
  for (const key of ['webm-vp9', 'webm-vp8', 'mp4-avc'] as const) {
    try {
      result[key] = await canEncodeVideo(ANIMATION_FORMATS[key].codec, {
        width: evenSize(size.width),
        height: evenSize(size.height),
        frameRate: size.fps,
        quality: VIDEO_QUALITY,
      });
    } catch {
      result[key] = false;
    }
  }
  return result;
}
