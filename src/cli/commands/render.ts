/**
 * `kleinflow render graph.json -o out.png [--size WxH] [--samples N] [--time T]`: the CPU picture
 * as a PNG; with `--frames`, an animation as a PNG sequence or a GIF (src/cli/render-animation.ts).
 */
import { LIMITS } from '../../../nodes/core/scene.ts';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
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
  parseTimeOption,
  runAnimationCommand,
} from '../render-animation-command.ts';
import { announceEstimate, estimateRenderSeconds } from '../render-estimate.ts';
import { renderScene3dPng, renderScenePng } from '../render-png.ts';

export const DEFAULT_RENDER_SIZE = { width: 1024, height: 1024 } as const;
/** Sample count × pixels above which a progress line is worth showing (a few seconds of work). */
const PROGRESS_WORK = 1 << 22;

const OPTIONS: readonly OptionSpec[] = [
  { long: 'output', short: 'o', value: 'FILE', doc: 'the PNG to write (required)' },
  {
    long: 'size',
    short: 's',
    value: 'WxH',
    doc: `image size in pixels, e.g. 1920x1080 (default ${DEFAULT_RENDER_SIZE.width}x${DEFAULT_RENDER_SIZE.height})`,
  },
  { long: 'samples', short: 'n', value: 'N', doc: "samples per pixel (default: the render node's)" },
  ...ANIMATION_OPTIONS,
];

export const renderCommand: CliCommand = {
  name: 'render',
  summary: 'render a graph to a PNG on the CPU (the graph is embedded in the PNG)',
  usage: [
    'Usage: kleinflow render GRAPH -o OUT.png [--size WxH] [--samples N] [--time T]',
    '       kleinflow render GRAPH --frames N|loop [--fps F] --out DIR/|OUT.gif [--frame-range A:B]',
    '',
    'Renders the graph with the CPU interpreter at its saved view. The view height fills the',
    'image height; a wider image shows more to the sides. GRAPH is a .json document or a PNG',
    'exported by Kleinflow. A 3D graph (a render-3d node) is drawn by the CPU sphere tracer from',
    'its camera (still pictures only: --time and --frames need a 2D graph).',
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
    const any = await loadAnyScene(io, graphPath);
    if (any.picture.kind === '3d') {
      if (time !== 0) throw usageError('--time needs a 2D graph: a 3D graph renders one still picture');
      return render3d(io, any.picture.scene3d, any.text, output, width, height, samples);
    }
    const loaded = { ...any, scene: any.picture.scene };
    // --time T: the same graph, its time-driven values at T (nodes/graph/evaluate.ts).
    const load = time === 0 ? loaded : { ...loaded, scene: sceneAt(loaded.doc!, time) };
    const used = samples ?? load.scene.samples;
    const label = `rendering ${output} (${width}×${height}, ${used} samples/px)`;
    const long = width * height * used >= PROGRESS_WORK;
    if (long) announceEstimate(io.stderr, label, estimateRenderSeconds(load.scene, width, height, used));
    return writeStill(io, output, label, long, `${width}×${height}, ${used} samples/px`, (onProgress) =>
      renderScenePng(load.scene, load.text, { width, height, samples: used, onProgress }),
    );
  },
};

/** Draws one still (a progress line while it runs when `long`), writes it, says what was written. */
async function writeStill(
  io: CliIo,
  output: string,
  label: string,
  long: boolean,
  summary: string,
  draw: (onProgress?: (done: number) => void) => Uint8Array,
): Promise<number> {
  const started = performance.now();
  const progress = long ? progressLine(io.stderr, label) : undefined;
  const png = draw(progress && ((f) => progress.update(f)));
  progress?.finish();
  try {
    await io.writeFile(output, png);
  } catch (e) {
    throw new CliError(fileErrorMessage('write', output, e));
  }
  const seconds = ((performance.now() - started) / 1000).toFixed(2);
  io.stdout.write(`wrote ${output} (${summary}, ${seconds} s)\n`);
  return EXIT.ok;
}

/** The 3D still: the CPU sphere tracer, with a progress line on long renders. */
async function render3d(
  io: CliIo,
  scene: Scene3d,
  text: string | null,
  output: string,
  width: number,
  height: number,
  samples: number | undefined,
): Promise<number> {
  const used = samples ?? scene.samples;
  const label = `rendering ${output} (${width}×${height}, ${used} samples/px, sphere traced)`;
  // Sphere tracing costs far more per sample than the plane's IIS: progress from smaller work.
  const long = width * height * used >= PROGRESS_WORK / 16;
  return writeStill(io, output, label, long, `${width}×${height}, ${used} samples/px`, (onProgress) =>
    renderScene3dPng(scene, text, { width, height, samples: used, onProgress }),
  );
}
