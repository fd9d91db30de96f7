/**
 * The animation options of `kleinflow render` (--time, --frames, --fps, --out, --frame-range,
 * --threads): parsing and the run of a sequence. Kept apart from commands/render.ts so the still
 * render stays short.
 */
import { LIMITS } from '../../nodes/core/scene.ts';
import {
  ANIMATION_FORMATS,
  animationFormatOfPath,
  evenSize,
  isVideoFormat,
} from '../io/animation-formats.ts';
import {
  type OptionSpec,
  type ParsedArgs,
  parseIntegerOption,
  parseSizeOption,
  stringOption,
} from './args.ts';
import { type CliIo, EXIT, usageError } from './command.ts';
import { loadScene } from './load-graph.ts';
import { frameFileName, parseFrameRange, renderAnimation, resolveFrameCount } from './render-animation.ts';

export const DEFAULT_FPS = 24;
/** Default frame size of a sequence: smaller than a still's, frames are many. */
const DEFAULT_FRAME_SIZE = { width: 512, height: 512 };
/** Sample count × pixels × frames above which a progress line is worth showing. */
const PROGRESS_WORK = 1 << 22;

export const ANIMATION_OPTIONS: readonly OptionSpec[] = [
  { long: 'time', short: 't', value: 'T', doc: 'render the graph at animation time T seconds (default 0)' },
  { long: 'frames', value: 'N|loop', doc: 'render N frames at t = i/fps, or "loop": one exact loop' },
  { long: 'fps', value: 'F', doc: `frames per second of --frames (default ${DEFAULT_FPS})` },
  {
    long: 'out',
    value: 'DIR/|X.gif|X.webm|X.mp4',
    doc: 'with --frames: a folder of frame-NNNNN.png, a looping GIF, or a WebM (VP9) / MP4 (H.264) video',
  },
  {
    long: 'frame-range',
    value: 'A:B',
    doc: 'with --frames: only frames A to B−1 (split work across machines)',
  },
  {
    long: 'threads',
    value: 'N',
    doc: 'worker threads of --frames and of a 3D graph (default: every core)',
  },
];

export const ANIMATION_USAGE = [
  'Animations: --time T renders one frame; --frames renders frame i at t = i/fps on every core.',
  'The same input gives the same bytes, and frames are independent: --frame-range 0:120 on one',
  'machine and 120:240 on another write the files of one sequence. A video needs even sides: an',
  'odd --size is rendered one pixel narrower or lower.',
];

/** --time T: a finite number of seconds (decimal, may be negative). */
export function parseTimeOption(parsed: ParsedArgs): number {
  const text = stringOption(parsed, 'time');
  if (text === undefined) return 0;
  const t = Number(text);
  if (!/^-?\d+(\.\d+)?$/.test(text) || !Number.isFinite(t))
    throw usageError(`--time expects seconds such as 2.5, got "${text}"`);
  return t;
}

/** --threads N (undefined: every core). */
export function parseThreadsOption(parsed: ParsedArgs): number | undefined {
  const text = stringOption(parsed, 'threads');
  return text ? parseIntegerOption('threads', text, 1, 1024) : undefined;
}

export async function runAnimationCommand(parsed: ParsedArgs, graphPath: string, io: CliIo): Promise<number> {
  const out = stringOption(parsed, 'out') ?? stringOption(parsed, 'output');
  if (!out) throw usageError('missing --out DIR/, OUT.gif, OUT.webm or OUT.mp4 (where to write the frames)');
  if (stringOption(parsed, 'time') !== undefined)
    throw usageError('--time renders one frame; with --frames the times are i/fps');
  const fpsText = stringOption(parsed, 'fps');
  const fps = fpsText ? parseIntegerOption('fps', fpsText, 1, 240) : DEFAULT_FPS;
  const sizeText = stringOption(parsed, 'size');
  const asked = sizeText ? parseSizeOption('size', sizeText, LIMITS.maxImageSide) : DEFAULT_FRAME_SIZE;
  const format = animationFormatOfPath(out);
  const video = format !== undefined && isVideoFormat(format);
  // 4:2:0 video halves the chroma both ways, so H.264 (and the browser's encoders) want even sides.
  const width = video ? evenSize(asked.width) : asked.width;
  const height = video ? evenSize(asked.height) : asked.height;
  if (width !== asked.width || height !== asked.height)
    io.stderr.write(
      `note: a video needs even sides: ${asked.width}×${asked.height} is rendered at ${width}×${height}\n`,
    );
  const samplesText = stringOption(parsed, 'samples');
  const threads = parseThreadsOption(parsed);
  const load = await loadScene(io, graphPath);
  const samples = samplesText
    ? parseIntegerOption('samples', samplesText, 1, LIMITS.maxSamples)
    : load.scene.samples;
  const frames = resolveFrameCount(
    stringOption(parsed, 'frames')!,
    fps,
    load.doc!,
    load.evaluation!,
    (line) => io.stderr.write(`${line}\n`),
  );
  const rangeText = stringOption(parsed, 'frame-range');
  const range = rangeText ? parseFrameRange(rangeText, frames) : { start: 0, end: frames };
  const started = performance.now();
  const count = range.end - range.start;
  await renderAnimation(io, {
    text: load.text,
    frames,
    fps,
    range,
    out,
    width,
    height,
    samples,
    threads,
    progress: width * height * samples * count >= PROGRESS_WORK,
  });
  const seconds = ((performance.now() - started) / 1000).toFixed(2);
  const what = format
    ? `${out} (${ANIMATION_FORMATS[format].label}, ${+(count / fps).toFixed(3)} s)`
    : `${out} (${frameFileName(range.start, frames)} … ${frameFileName(range.end - 1, frames)})`;
  io.stdout.write(
    `wrote ${count} frame${count === 1 ? '' : 's'} of ${frames} at ${fps} fps → ${what} (${width}×${height}, ${samples} samples/px, ${seconds} s)\n`,
  );
  return EXIT.ok;
}
