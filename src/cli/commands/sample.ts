/**
 * `kleinflow sample graph.json --points pts.json`: runs the IIS at given points (no clipping, no
 * colour) and prints `{"points":[{"depth":…,"x":…,"y":…,"escaped":…},…]}` in input order, where
 * (x, y) is the final point. For scripts, plots and checking other implementations.
 */
import type { Vec2 } from '../../../nodes/core/values.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { expectPositionals, formatOptions, type OptionSpec, parseArgs, stringOption } from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { documentText, loadScene, readInput } from '../load-graph.ts';

const OPTIONS: readonly OptionSpec[] = [
  { long: 'points', short: 'p', value: 'FILE', doc: 'JSON array of [x, y] world points (required)' },
];

const describe = (v: unknown): string => {
  if (Array.isArray(v)) return `an array of ${v.length}`;
  if (v === null) return 'null';
  if (typeof v === 'object') return 'an object';
  const s = JSON.stringify(v) ?? String(v);
  return s.length > 40 ? `${s.slice(0, 37)}...` : s;
};

/** Parses `[[x, y], …]`; any problem is one message naming the file and the first bad entry. */
export function parsePoints(path: string, text: string): Vec2[] {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (e) {
    throw new CliError(`"${path}" is not valid JSON: ${(e as Error).message}`);
  }
  if (!Array.isArray(value)) {
    throw new CliError(`"${path}": expected an array of [x, y] points, got ${describe(value)}`);
  }
  value.forEach((p, i) => {
    const ok =
      Array.isArray(p) && p.length === 2 && p.every((c) => typeof c === 'number' && Number.isFinite(c));
    if (!ok)
      throw new CliError(`"${path}"[${i}]: expected [x, y] with two finite numbers, got ${describe(p)}`);
  });
  return value as Vec2[];
}

export const sampleCommand: CliCommand = {
  name: 'sample',
  summary: 'print depth, final point and escaped flag of the IIS at given points (JSON)',
  usage: [
    'Usage: kleinflow sample GRAPH --points POINTS.json',
    '',
    'POINTS.json holds [[x, y], ...] in world coordinates. Prints, in the same order,',
    '{"points":[{"depth":D,"x":X,"y":Y,"escaped":E}, ...]} where (X, Y) is the final point of the',
    'IIS loop, D the number of steps and E whether it reached the tile (false: still moving at',
    'max iterations, on or near the limit set). The clip disk and colours do not apply.',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    const pointsPath = stringOption(parsed, 'points');
    if (!pointsPath) throw usageError('missing --points POINTS.json');
    const points = parsePoints(pointsPath, documentText(pointsPath, await readInput(io, pointsPath)));
    const { scene } = await loadScene(io, graphPath);
    const results = points.map((p) => {
      const r = interpret(scene, p);
      return { depth: r.depth, x: r.final[0], y: r.final[1], escaped: r.escaped };
    });
    io.stdout.write(`${JSON.stringify({ points: results })}\n`);
    return EXIT.ok;
  },
};
