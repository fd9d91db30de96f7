/**
 * `kleinflow render graph.json -o out.png [--size WxH] [--samples N] [--time T]`: the CPU picture
 * as a PNG; with `--frames`, an animation as a PNG sequence or a GIF (src/cli/render-animation.ts).
 */
import { LIMITS } from '../../../nodes/core/scene.ts';
import {
  expectPositionals,
  formatOptions,
  type OptionSpec,
  parseArgs,
  parseIntegerOption,
  parseSizeOption,
  stringOption,
} from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { sceneAt } from '../frame-render.ts';
import { fileErrorMessage, loadScene } from '../load-graph.ts';
import { progressLine } from '../progress.ts';
import {
  ANIMATION_OPTIONS,
  ANIMATION_USAGE,
  parseTimeOption,
  runAnimationCommand,
} from '../render-animation-command.ts';
import { announceEstimate, estimateRenderSeconds } from '../render-estimate.ts';
import { renderScenePng } from '../render-png.ts';

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
    'exported by Kleinflow.',
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
    const loaded = await loadScene(io, graphPath);
    // --time T: the same graph, its time-driven values at T (nodes/graph/evaluate.ts).
    const load = time === 0 ? loaded : { ...loaded, scene: sceneAt(loaded.doc!, time) };
    const used = samples ?? load.scene.samples;
    const label = `rendering ${output} (${width}×${height}, ${used} samples/px)`;
    const long = width * height * used >= PROGRESS_WORK;
    if (long) announceEstimate(io.stderr, label, estimateRenderSeconds(load.scene, width, height, used));
    const started = performance.now();
    const progress = long ? progressLine(io.stderr, label) : undefined;
    const png = renderScenePng(load.scene, load.text, {
      width,
      height,
      samples: used,
      onProgress: progress && ((f) => progress.update(f)),
    });
    progress?.finish();
    try {
      await io.writeFile(output, png);
    } catch (e) {
      throw new CliError(fileErrorMessage('write', output, e));
    }
    const seconds = ((performance.now() - started) / 1000).toFixed(2);
    io.stdout.write(`wrote ${output} (${width}×${height}, ${used} samples/px, ${seconds} s)\n`);
    return EXIT.ok;
  },
};
