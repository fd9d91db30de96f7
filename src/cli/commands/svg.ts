/**
 * `kleinflow svg GRAPH --out OUT.svg [--min-radius PX] [--size WxH]`: the graph's tile edges and seed
 * disks as SVG circles and lines (shader-gen/vector), for graphs built from mirrors: inversions,
 * reflections and two-circle Möbius generators.
 */
import { LIMITS } from '../../../nodes/core/scene.ts';
import { exportSvg, MAX_VECTOR_ELEMENTS } from '../../../shader-gen/vector/index.ts';
import {
  expectPositionals,
  formatOptions,
  type OptionSpec,
  parseArgs,
  parseSizeOption,
  stringOption,
} from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { fileErrorMessage, loadScene } from '../load-graph.ts';
import { DEFAULT_RENDER_SIZE } from './render.ts';

/** Circles smaller than this many output pixels (radius) are left out by default. */
export const DEFAULT_MIN_RADIUS = 1;

const OPTIONS: readonly OptionSpec[] = [
  { long: 'out', short: 'o', value: 'FILE', doc: 'the SVG to write (required)' },
  {
    long: 'size',
    short: 's',
    value: 'WxH',
    doc: `image size in pixels (default ${DEFAULT_RENDER_SIZE.width}x${DEFAULT_RENDER_SIZE.height})`,
  },
  {
    long: 'min-radius',
    value: 'PX',
    doc: `leave out circles under PX output pixels in radius (default ${DEFAULT_MIN_RADIUS})`,
  },
];

function parseMinRadius(text: string): number {
  const v = Number(text);
  if (!/^\d+(\.\d+)?$/.test(text) || !(v > 0)) {
    throw usageError(`--min-radius expects a positive number of pixels, got "${text}"`);
  }
  return v;
}

export const svgCommand: CliCommand = {
  name: 'svg',
  summary: 'write the tile edges and seed disks as SVG circles and lines',
  usage: [
    'Usage: kleinflow svg GRAPH --out OUT.svg [--min-radius PX] [--size WxH]',
    '',
    "Enumerates the images of the graph's mirrors (and seed disks) at its saved view down to",
    'the minimum radius and writes them as SVG circles and lines in the tile colours, clipped to',
    `the view and the render's clip disk. At most ${MAX_VECTOR_ELEMENTS} elements. Works for graphs`,
    "made of inversions, reflections and two-circle Möbius generators. The render node's figures",
    '(Cayley graph, depth-first limit set) are drawn over it; for matrix generators the figures',
    'alone are written.',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    const output = stringOption(parsed, 'out');
    if (!output) throw usageError('missing --out OUT.svg (where to write the picture)');
    const sizeText = stringOption(parsed, 'size');
    const { width, height } = sizeText
      ? parseSizeOption('size', sizeText, LIMITS.maxImageSide)
      : DEFAULT_RENDER_SIZE;
    const radiusText = stringOption(parsed, 'min-radius');
    const minRadius = radiusText === undefined ? DEFAULT_MIN_RADIUS : parseMinRadius(radiusText);

    const { scene } = await loadScene(io, graphPath);
    const result = exportSvg(scene, { width, height, minRadius });
    if (!result.ok) throw new CliError(`${graphPath}: no vector export: ${result.message}`);
    try {
      await io.writeFile(output, result.svg);
    } catch (e) {
      throw new CliError(fileErrorMessage('write', output, e));
    }
    const figures = result.figureCount > 0 ? `, ${result.figureCount} figure strokes and points` : '';
    io.stdout.write(
      `wrote ${output} (${width}×${height}, ${result.edgeCount} edges and ${result.seedCount} seed disks${figures}, radius ≥ ${minRadius} px)\n`,
    );
    for (const note of result.notes) io.stderr.write(`note: ${note}\n`);
    return EXIT.ok;
  },
};
