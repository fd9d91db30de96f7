/**
 * The file formats of "Export animation…": WebM (VP9 or VP8) and MP4 (H.264) encoded by the
 * browser's WebCodecs and muxed by mediabunny, or a GIF (gifenc, src/io/gif.ts) that needs no
 * codec. Which video codecs a browser has varies (headless Chromium builds often lack H.264):
 * `supportedFormats` asks the encoder itself (VideoEncoder.isConfigSupported, through
 * mediabunny's canEncodeVideo) before the dialog offers a format. Loaded on demand (import()),
 * so the encoders stay out of the editor's start-up bundle.
 */
import {
  BufferTarget,
  canEncodeVideo,
  Mp4OutputFormat,
  Output,
  QUALITY_HIGH,
  VideoSample,
  VideoSampleSource,
  WebMOutputFormat,
} from 'mediabunny';
import { gifWriter } from '../io/gif.ts';
import { ANIMATION_FORMATS, type AnimationFormat, evenSize, type FrameSize } from './animation-formats.ts';

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
        quality: QUALITY_HIGH,
      });
    } catch {
      result[key] = false;
    }
  }
  return result;
}

/** Takes the frames in order (RGBA, row 0 at the top) and makes the file. */
export interface FrameSink {
  add(pixels: Uint8ClampedArray, index: number): Promise<void>;
  finish(): Promise<Uint8Array>;
  cancel(): Promise<void>;
}

export async function createSink(format: AnimationFormat, size: FrameSize): Promise<FrameSink> {
  const { width, height, fps } = size;
  if (format === 'gif') {
    const gif = gifWriter(fps);
    return {
      add: async (data) => gif.addFrame({ width, height, data }),
      finish: async () => gif.finish(),
      cancel: async () => undefined,
    };
  }
  const spec = ANIMATION_FORMATS[format];
  const target = new BufferTarget();
  const output = new Output({
    format: spec.extension === 'mp4' ? new Mp4OutputFormat() : new WebMOutputFormat(),
    target,
  });
  const source = new VideoSampleSource({ codec: spec.codec, quality: QUALITY_HIGH });
  output.addVideoTrack(source, { frameRate: fps });
  await output.start();
  return {
    async add(pixels, index) {
      // Timestamps from the frame number (i/fps), like the frames' times: no drift.
      const sample = new VideoSample(pixels, {
        format: 'RGBA',
        codedWidth: width,
        codedHeight: height,
        timestamp: index / fps,
        duration: 1 / fps,
      });
      try {
        await source.add(sample);
      } finally {
        sample.close();
      }
    },
    async finish() {
      await output.finalize();
      if (!target.buffer) throw new Error('the video muxer produced no file');
      return new Uint8Array(target.buffer);
    },
    cancel: () => output.cancel(),
  };
}
