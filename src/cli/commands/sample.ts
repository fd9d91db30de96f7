/**
 * `kleinflow sample graph.json --points pts.json`: runs the IIS at given points (no clipping, no
 * colour) and prints `{"points":[{"depth":…,"x":…,"y":…,"escaped":…},…]}` in input order, where
 * (x, y) is the final point. A 3D graph takes [x, y, z] points and adds z and the signed distance
 * to the seeds' orbit. For scripts, plots and checking other implementations.
 */
import type { Scene3d, Vec3 } from '../../../nodes/core/scene-3d.ts';
import { sampleSpace } from '../../../nodes/core/seed-3d.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { formatBytes, INPUT_LIMITS } from '../../io/input-limits.ts';
import { expectPositionals, formatOptions, type OptionSpec, parseArgs, stringOption } from '../args.ts';
import { type CliCommand, CliError, EXIT, type InputFile, usageError } from '../command.ts';
import { type AnyScene, fileErrorMessage, loadAnyScene } from '../load-graph.ts';
import { streamPoints } from '../points-stream.ts';
import { progressLine } from '../progress.ts';

const OPTIONS: readonly OptionSpec[] = [
  {
    long: 'points',
    short: 'p',
    value: 'FILE',
    doc: 'JSON array of [x, y] world points, [x, y, z] for a 3D graph (required)',
  },
];

/** Output is written in pieces of about this many characters (then the reader may catch up). */
const OUT_PIECE = 1 << 16;
/** Points files at least this big (about a million points) show progress on stderr. */
const PROGRESS_BYTES = 16 * 1024 * 1024;

/** A JSON number as JSON.stringify writes it (−0 as 0, non-finite as null). */
const num = (v: number): string => (Number.isFinite(v) ? String(v) : 'null');

/** One point of a 3D graph: the IIS in space and the estimated signed distance to the seeds' orbit. */
function sample3d(scene: Scene3d, p: Vec3): string {
  const r = sampleSpace(scene, p);
  const [x, y, z] = r.point;
  const d = r.distance === null ? 'null' : num(r.distance);
  return `{"depth":${r.depth},"x":${num(x)},"y":${num(y)},"z":${num(z)},"escaped":${r.escaped},"distance":${d}}`;
}

/** Every point of the file as one JSON object each, 2D or 3D as the graph is. */
function sampler(path: string, file: InputFile, picture: AnyScene, onBytes?: (b: number) => void) {
  if (picture.kind === '3d') {
    const scene = picture.scene3d;
    return mapBatches(streamPoints(path, file.chunks, { dimension: 3, onBytes }), (p) => sample3d(scene, p));
  }
  const scene = picture.scene;
  return mapBatches(streamPoints(path, file.chunks, { onBytes }), (p) => {
    const r = interpret(scene, p);
    return `{"depth":${r.depth},"x":${num(r.final[0])},"y":${num(r.final[1])},"escaped":${r.escaped}}`;
  });
}

async function* mapBatches<P>(batches: AsyncIterable<P[]>, f: (p: P) => string): AsyncGenerator<string[]> {
  for await (const batch of batches) yield batch.map(f);
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
    'A 3D graph (a render-3d node) takes [[x, y, z], ...] and prints',
    '{"depth":D,"x":X,"y":Y,"z":Z,"escaped":E,"distance":S}: S is the signed distance from the',
    'point to the nearest image of a seed (negative inside), estimated as the seed distance at the',
    'final point divided by the accumulated scale factor; null when there are no seeds.',
    '',
    'The points are read and the results written as a stream: any number of points works in',
    'bounded memory, and output starts at once (--points - reads standard input). One entry may',
    `be at most ${formatBytes(INPUT_LIMITS.pointEntryChars)}; GRAPH at most ${formatBytes(INPUT_LIMITS.documentBytes)} (a PNG ${formatBytes(INPUT_LIMITS.pngBytes)}). A points file of`,
    `${formatBytes(PROGRESS_BYTES)} or more shows progress on stderr. A bad entry ends the command with exit`,
    '1 and one line naming it; the results before it may already have been printed.',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    const pointsPath = stringOption(parsed, 'points');
    if (!pointsPath) throw usageError('missing --points POINTS.json');
    const { picture } = await loadAnyScene(io, graphPath);
    let file: InputFile;
    try {
      file = await io.open(pointsPath);
    } catch (e) {
      throw new CliError(fileErrorMessage('read', pointsPath, e));
    }
    const size = file.size;
    const progress =
      size !== null && size >= PROGRESS_BYTES
        ? progressLine(io.stderr, `sampling ${pointsPath} (${formatBytes(size)})`)
        : undefined;
    // The result streams out as the points stream in: nothing grows with the number of points.
    let out = '{"points":[';
    let count = 0;
    let written = false;
    const flush = async () => {
      io.stdout.write(out);
      written = true;
      out = '';
      await io.stdout.drain?.();
    };
    try {
      const results = sampler(pointsPath, file, picture, progress && ((b) => progress.update(b / size!)));
      for await (const batch of results) {
        for (const line of batch) {
          out += `${count === 0 ? '' : ','}${line}`;
          count++;
          if (out.length >= OUT_PIECE) await flush();
        }
      }
    } catch (e) {
      progress?.finish();
      // Points already written stay written (they are right); say that the output stops early.
      if (e instanceof CliError && written)
        throw new CliError(`${e.message} (the output is incomplete: it stops after ${count} points)`);
      throw e;
    }
    out += ']}\n';
    await flush();
    progress?.finish();
    return EXIT.ok;
  },
};
