/**
 * The video files of an animation: WebM (VP9 or VP8) or MP4 (H.264), muxed by mediabunny. The
 * encoder is whatever mediabunny has: the browser's WebCodecs, or in Node the libavcodec encoders
 * that @mediabunny/server registers (src/cli/video-encoders.ts). Codec, container and bitrate are
 * chosen here once, for the editor's export and the CLI alike.
 */
import {
  BufferTarget,
  Mp4OutputFormat,
  Output,
  QUALITY_HIGH,
  VideoSample,
  VideoSampleSource,
  WebMOutputFormat,
} from 'mediabunny';
import { ANIMATION_FORMATS, type FrameSink, type FrameSize, type VideoFormat } from './animation-formats.ts';

/** Bitrate of every video: mediabunny's "high" (its bitrate grows with the frame's pixel count). */
export const VIDEO_QUALITY = QUALITY_HIGH;

/** A video sink; `size` must have even sides (4:2:0 chroma, animation-formats.ts evenSize). */
export async function createVideoSink(format: VideoFormat, size: FrameSize): Promise<FrameSink> {
  const { width, height, fps } = size;
  const spec = ANIMATION_FORMATS[format];
  const target = new BufferTarget();
  const output = new Output({
    format: spec.extension === 'mp4' ? new Mp4OutputFormat() : new WebMOutputFormat(),
    target,
  });
  const source = new VideoSampleSource({ codec: spec.codec, quality: VIDEO_QUALITY });
  output.addVideoTrack(source, { frameRate: fps });
  await output.start();
  return {
    async add(pixels, index) {
      // Timestamps from the frame number (i/fps), like the frames' times: no drift, and n frames
      // last exactly n/fps, so a loop's last frame is shown for one frame and then the first.
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
