/**
 * `kleinflow render GRAPH --frames N|loop --fps F --out DIR/|x.gif|x.webm|x.mp4 [--frame-range A:B]`:
 * frame i at t = i/fps (nodes/graph/frame-times.ts), rendered on every core (one worker thread
 * each), written as DIR/frame-NNNNN.png or, in order, into one file: a looping GIF or a video
 * (src/io/animation-sink.ts, the editor's export's writer). The frame numbers are global:
 * `--frame-range 0:50` on one machine and `50:100` on another give the files of one sequence.
 */
import { mkdir } from 'node:fs/promises';
import { availableParallelism } from 'node:os';
import { join } from 'node:path';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { Evaluation } from '../../nodes/graph/evaluate.ts';
import { loopFrameCount, loopIsFrameExact } from '../../nodes/graph/frame-times.ts';
import { loopPeriod } from '../../nodes/graph/loop-period.ts';
import {
  type AnimationFormat,
  animationFormatOfPath,
  type FrameSink,
  isVideoFormat,
} from '../io/animation-formats.ts';
import { createSink } from '../io/animation-sink.ts';
import { parseIntegerOption } from './args.ts';
import { CliError, type CliIo, errorMessage, usageError } from './command.ts';
import type { FrameJob, FrameResult } from './frame-job.ts';
import { fileErrorMessage } from './load-graph.ts';
import { progressLine } from './progress.ts';
import { loadVideoEncoders } from './video-encoders.ts';
import { runPool } from './worker-pool.ts';

/** The most frames one command renders (an hour at 30 fps would be 108 000: split it with --frame-range). */
export const MAX_FRAMES = 100_000;

/** "A:B" → frames A … B−1 (either end may be left out: "A:" to the last frame, ":B" from 0). */
export function parseFrameRange(text: string, frames: number): { start: number; end: number } {
  const m = /^(\d*):(\d*)$/.exec(text);
  if (!m) throw usageError(`--frame-range expects A:B (frames A to B−1, e.g. 0:48), got "${text}"`);
  const start = m[1] === '' ? 0 : parseIntegerOption('frame-range', m[1], 0, frames);
  const end = m[2] === '' ? frames : parseIntegerOption('frame-range', m[2], 0, frames);
  if (start >= end) throw usageError(`--frame-range ${text} holds no frame (the end is exclusive)`);
  return { start, end };
}

/** frame-00042.png: zero-padded to the width of the last frame number of the whole sequence, so names sort. */
export function frameFileName(index: number, frames: number): string {
  return `frame-${String(index).padStart(Math.max(5, String(frames - 1).length), '0')}.png`;
}

/**
 * --frames N, or "loop": the graph's loop period (nodes/graph/loop-period.ts) × fps; a loop that
 * is not a whole number of frames at this fps gets a warning on `warn` (it cannot close exactly).
 */
export function resolveFrameCount(
  text: string,
  fps: number,
  doc: GraphDoc,
  evaluation: Evaluation,
  warn: (line: string) => void,
): number {
  if (text !== 'loop') return parseIntegerOption('frames', text, 1, MAX_FRAMES);
  const period = loopPeriod(doc, evaluation);
  if (period.kind === 'none') throw new CliError(`--frames loop: ${period.reason}`);
  if (period.kind === 'static') throw new CliError('--frames loop: nothing in the graph changes with time');
  const frames = loopFrameCount(period.seconds, fps);
  if (frames > MAX_FRAMES)
    throw new CliError(`--frames loop: one loop is ${frames} frames at ${fps} fps, over ${MAX_FRAMES}`);
  if (!loopIsFrameExact(period.seconds, fps))
    warn(
      `warning: one loop is ${+period.seconds.toFixed(6)} s, not a whole number of frames at ${fps} fps: ${frames} frames close it to within half a frame`,
    );
  return frames;
}

export interface AnimationRequest {
  readonly text: string;
  readonly frames: number;
  readonly fps: number;
  readonly range: { readonly start: number; readonly end: number };
  readonly out: string;
  readonly width: number;
  readonly height: number;
  readonly samples: number;
  /** Worker threads (default: every core). */
  readonly threads?: number;
  /** Whether to draw a progress line on stderr (worth it for long renders only). */
  readonly progress?: boolean;
}

/** The file's sink (a video loads its encoders first), or undefined for a folder of PNGs. */
async function openSink(format: AnimationFormat | undefined, request: AnimationRequest) {
  if (!format) return undefined;
  if (isVideoFormat(format)) await loadVideoEncoders();
  const { width, height, fps } = request;
  try {
    return await createSink(format, { width, height, fps });
  } catch (e) {
    throw new CliError(`cannot encode ${request.out}: ${errorMessage(e)}`);
  }
}

export async function renderAnimation(io: CliIo, request: AnimationRequest): Promise<void> {
  const { start, end } = request.range;
  const format = animationFormatOfPath(request.out);
  if (!format) {
    try {
      await mkdir(request.out, { recursive: true });
    } catch (e) {
      throw new CliError(fileErrorMessage('write', request.out, e));
    }
  }
  const sink = await openSink(format, request);
  const jobs: FrameJob[] = [];
  for (let index = start; index < end; index++) {
    const { text, fps, width, height, samples } = request;
    jobs.push({ text, index, fps, width, height, samples, encode: sink ? 'rgba' : 'png' });
  }
  // Results arrive in any order: a file takes them in frame order, PNGs are written as they come.
  const waiting = new Map<number, Uint8Array>();
  let next = start;
  let encoding: Promise<void> = Promise.resolve();
  const writes: Promise<void>[] = [];
  let failure: string | undefined;
  const progress = request.progress ? progressLine(io.stderr, `rendering ${end - start} frames`) : undefined;
  let done = 0;
  const take = (s: FrameSink, data: Uint8Array, index: number) => {
    // One encode at a time, in order; the file's first frame is at 0 s whatever the range.
    encoding = encoding
      .then(() => (failure ? undefined : s.add(data, index - start)))
      .catch((e) => {
        failure ??= `cannot encode frame ${index} into ${request.out}: ${errorMessage(e)}`;
      });
  };
  await runPool<FrameJob, FrameResult>(
    new URL('./frame-job.ts', import.meta.url),
    jobs,
    request.threads ?? availableParallelism(),
    (r) => {
      progress?.update(++done / jobs.length);
      if ('error' in r) {
        failure ??= `frame ${r.index}: ${r.error}`;
        return;
      }
      if (!sink) {
        const path = join(request.out, frameFileName(r.index, request.frames));
        writes.push(
          io.writeFile(path, r.bytes).catch((e) => {
            failure ??= fileErrorMessage('write', path, e);
          }),
        );
        return;
      }
      waiting.set(r.index, r.bytes);
      for (let data = waiting.get(next); data; data = waiting.get(next)) {
        take(sink, data, next);
        waiting.delete(next++);
      }
    },
  ).catch(async (e) => {
    await sink?.cancel().catch(() => undefined);
    throw e;
  });
  progress?.finish();
  await Promise.all([...writes, encoding]);
  if (failure) {
    await sink?.cancel().catch(() => undefined);
    throw new CliError(failure);
  }
  if (!sink) return;
  const bytes = await sink.finish().catch((e) => {
    throw new CliError(`cannot encode ${request.out}: ${errorMessage(e)}`);
  });
  try {
    await io.writeFile(request.out, bytes);
  } catch (e) {
    throw new CliError(fileErrorMessage('write', request.out, e));
  }
}
