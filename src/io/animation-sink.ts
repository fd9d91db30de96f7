/**
 * Writes the frames of an animation into one file, shared by the editor's "Export animation…"
 * and `kleinflow render --frames … --out x.webm|x.mp4|x.gif`: a GIF (gifenc, gif.ts) needs no
 * codec; a video (video-sink.ts) is loaded only when asked for, so a GIF never loads mediabunny.
 */
import type { AnimationFormat, FrameSink, FrameSize } from './animation-formats.ts';
import { gifWriter } from './gif.ts';

/** A sink for `format` at `size`; a video's sides must be even (animation-formats.ts evenSize). */
export async function createSink(format: AnimationFormat, size: FrameSize): Promise<FrameSink> {
  if (format !== 'gif') return (await import('./video-sink.ts')).createVideoSink(format, size);
  const { width, height, fps } = size;
  const gif = gifWriter(fps);
  return {
    add: async (data) => gif.addFrame({ width, height, data }),
    finish: async () => gif.finish(),
    cancel: async () => undefined,
  };
}
