/**
 * `kleinflow render graph.json -o out.png [--size WxH] [--samples N] [--time T]`: the CPU picture
 * as a PNG; with `--frames`, an animation as a PNG sequence or a GIF (src/cli/render-animation.ts).
 */
import { availableParallelism } from 'node:os';
import { LIMITS } from '../../../nodes/core/scene.ts';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { type SpaceViewTarget, spaceViewTarget } from '../../../nodes/graph/space-view.ts';
import {
  expectPositionals,
  formatOptions,
  type OptionSpec,
  parseArgs,
  parseIntegerOption,
  parseSizeOption,
  stringOption,
} from '../args.ts';
import { type CliCommand, CliError, type CliIo, EXIT, usageError } from '../command.ts';
import { sceneAt } from '../frame-render.ts';
import { fileErrorMessage, loadAnyScene } from '../load-graph.ts';
import { progressLine } from '../progress.ts';
import {
  ANIMATION_OPTIONS,
  ANIMATION_USAGE,
  parseThreadsOption,
  parseTimeOption,
  runAnimationCommand,
} from '../render-animation-command.ts';
import { announceEstimate, estimate3d, estimateRenderSeconds } from '../render-estimate.ts';
import { renderScene3dPngOnPool, renderScenePng } from '../render-png.ts';

export const DEFAULT_RENDER_SIZE = { width: 1024, height: 1024 } as const;
/** Sample count × pixels above which a progress line is worth showing (a few seconds of work). */
const PROGRESS_WORK = 1 << 22;
/** A 3D render estimated shorter than this (s) on one thread is not worth starting workers for. */
const WORKERS_AFTER_S = 1;

const OPTIONS: readonly OptionSpec[] = [
  { long: 'output', short: 'o', value: 'FILE', doc: 'the PNG to write (required)' },
  {
    long: 'size',
    short: 's',
    value: 'WxH',
    doc: `image size in pixels, e.g. 1920x1080 (default ${DEFAULT_RENDER_SIZE.width}x${DEFAULT_RENDER_SIZE.height})`,
  },
  { long: 'samples', short: 'n', value: 'N', doc: "samples per pixel (default: the render node's)" },
  {
    long: 'progress',
    doc: 'always print the time estimate and progress (default: for renders that take a while)',
  },
  ...ANIMATION_OPTIONS,
];

export const renderCommand: CliCommand = {
  name: 'render',
  summary: 'render a graph to a PNG on the CPU (the graph is embedded in the PNG)',
  usage: [
    'Usage: kleinflow render GRAPH -o OUT.png [--size WxH] [--samples N] [--time T]',
    '       kleinflow render GRAPH --frames N|loop [--fps F] --out DIR/|OUT.gif|OUT.webm|OUT.mp4 [--frame-range A:B]',
    '',
    'Renders the graph with the CPU interpreter at its saved view. The view height fills the',
    'image height; a wider image shows more to the sides. GRAPH is a .json document or a PNG',
    'exported by Kleinflow. A 3D graph (a render-3d node) is drawn by the CPU sphere tracer from',
    'its camera, on every core (still pictures only: --time and --frames need a 2D graph). A long',
    'render first says about how long it will take, then how far it is.',
    '',
    ...ANIMATION_USAGE,
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    if (stringOption(parsed, 'frames') !== undefined) return runAnimationCommand(parsed, graphPath, io);
    const output = stringOption(parsed, 'output');
    if (!output) throw usageError('missing -o OUT.png (where to write the picture)');
    const sizeText = stringOption(parsed, 'size');
    const { width, height } = sizeText
      ? parseSizeOption('size', sizeText, LIMITS.maxImageSide)
      : DEFAULT_RENDER_SIZE;
    const samplesText = stringOption(parsed, 'samples');
    const samples = samplesText
      ? parseIntegerOption('samples', samplesText, 1, LIMITS.maxSamples)
      : undefined;

    const time = parseTimeOption(parsed);
    const always = parsed.options.progress === true;
    const any = await loadAnyScene(io, graphPath);
    if (any.picture.kind === '3d') {
      if (time !== 0) throw usageError('--time needs a 2D graph: a 3D graph renders one still picture');
      const threads = parseThreadsOption(parsed);
      const space = any.doc ? spaceViewTarget(any.doc) : null;
      const request = { width, height, samples, threads, always, space };
      return render3d(io, any.picture.scene3d, any.text, output, request);
    }
    const loaded = { ...any, scene: any.picture.scene };
    // --time T: the same graph, its time-driven values at T (nodes/graph/evaluate.ts).
    const load = time === 0 ? loaded : { ...loaded, scene: sceneAt(loaded.doc!, time) };
    const used = samples ?? load.scene.samples;
    const summary = `${width}×${height}, ${used} samples/px`;
    // The probe costs a little: only renders big enough to take a while are estimated.
    const long = always || width * height * used >= PROGRESS_WORK;
    const seconds = long ? estimateRenderSeconds(load.scene, width, height, used) : undefined;
    const still = { label: `rendering ${output} (${summary})`, summary, seconds, always };
    return writeStill(io, output, still, (onProgress) =>
      renderScenePng(load.scene, load.text, { width, height, samples: used, onProgress }),
    );
  },
};

/** What writeStill says about a still. */
interface StillText {
  readonly label: string;
  readonly summary: string;
  /** The estimated time, when measured: announced if long (or `always`), and then progress shown. */
  readonly seconds: number | undefined;
  readonly always: boolean;
  /** What the estimate runs on (announceEstimate's default: the CPU). */
  readonly on?: string;
}

/**
 * Draws one still, its estimate first and a progress line while it runs when it takes a while
 * (the same for the plane and space), writes it, says what was written.
 */
async function writeStill(
  io: CliIo,
  output: string,
  still: StillText,
  draw: (onProgress?: (done: number) => void) => Uint8Array | Promise<Uint8Array>,
): Promise<number> {
  const started = performance.now();
  const { label, seconds, always, on } = still;
  const long = seconds !== undefined && announceEstimate(io.stderr, label, seconds, { always, on });
  const progress = long ? progressLine(io.stderr, label) : undefined;
  const png = await draw(progress && ((f) => progress.update(f)));
  progress?.finish();
  try {
    await io.writeFile(output, png);
  } catch (e) {
    throw new CliError(fileErrorMessage('write', output, e));
  }
  const took = ((performance.now() - started) / 1000).toFixed(2);
  io.stdout.write(`wrote ${output} (${still.summary}, ${took} s)\n`);
  return EXIT.ok;
}

interface Still3dRequest {
  readonly width: number;
  readonly height: number;
  readonly samples: number | undefined;
  /** Worker threads (undefined: every core, or this thread alone for a render of a moment). */
  readonly threads: number | undefined;
  readonly always: boolean;
  /** The graph's parameter-space view, drawn as a panel in the corner. */
  readonly space: SpaceViewTarget | null;
}

/**
 * The 3D still: the CPU sphere tracer (or volume renderer) in bands over worker threads (render-3d-pool.ts), the
 * estimate said before any of it starts. Starting workers costs about a second, so a render
 * estimated shorter than that stays on this thread unless --threads asks otherwise.
 */
async function render3d(
  io: CliIo,
  scene: Scene3d,
  text: string | null,
  output: string,
  request: Still3dRequest,
): Promise<number> {
  const { width, height } = request;
  const samples = request.samples ?? scene.samples;
  const { seconds: single, how } = estimate3d(scene, width, height, samples);
  const wanted = request.threads ?? (single < WORKERS_AFTER_S ? 1 : availableParallelism());
  const threads = Math.min(wanted, height);
  const summary = `${width}×${height}, ${samples} samples/px`;
  const still = {
    label: `rendering ${output} (${summary}, ${how})`,
    summary,
    seconds: single / threads,
    always: request.always,
    on: threads > 1 ? `${threads} CPU threads` : undefined,
  };
  const secondsPerRow = single / height;
  return writeStill(io, output, still, (onProgress) =>
    renderScene3dPngOnPool(
      scene,
      text,
      { width, height, samples, threads, secondsPerRow, onProgress },
      request.space,
    ),
  );
}
