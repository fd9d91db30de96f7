/**
 * `kleinflow mesh GRAPH --out MODEL.stl [--resolution N] [--bounds …]`: the solid of a 3D graph
 * (the orbit of its seeds) as a closed triangle mesh in binary STL, for 3D printing (paper §5.3.2;
 * docs/math-3d.md "Voxel mesh (paper §5.3.2)").
 */
import {
  type Bounds3,
  MAX_MESH_RESOLUTION,
  MIN_MESH_RESOLUTION,
  meshScene3d,
  parseBounds,
} from '../../../nodes/geometry/space/voxel-mesh.ts';
import { writeStl } from '../../io/stl.ts';
import {
  expectPositionals,
  formatOptions,
  type OptionSpec,
  parseArgs,
  parseIntegerOption,
  stringOption,
} from '../args.ts';
import { type CliCommand, CliError, EXIT, usageError } from '../command.ts';
import { fileErrorMessage, loadAnyScene } from '../load-graph.ts';
import { progressLine } from '../progress.ts';

export const DEFAULT_MESH_RESOLUTION = 64;

const OPTIONS: readonly OptionSpec[] = [
  { long: 'out', short: 'o', value: 'FILE', doc: 'the STL file to write (required)' },
  {
    long: 'resolution',
    short: 'r',
    value: 'N',
    doc: `voxels along the longest side, ${MIN_MESH_RESOLUTION}…${MAX_MESH_RESOLUTION} (default ${DEFAULT_MESH_RESOLUTION})`,
  },
  {
    long: 'bounds',
    value: 'X0,Y0,Z0,X1,Y1,Z1',
    doc: 'the box to mesh (the solid is cut flat at its sides); default: the orbit’s own box',
  },
];

function boundsOption(text: string): Bounds3 {
  const b = parseBounds(text);
  if (!b.ok) throw usageError(`--bounds ${b.error}`);
  return b.value;
}

export const meshCommand: CliCommand = {
  name: 'mesh',
  summary: 'write the solid of a 3D graph as a closed STL mesh (3D printing)',
  usage: [
    'Usage: kleinflow mesh GRAPH --out MODEL.stl [--resolution N] [--bounds X0,Y0,Z0,X1,Y1,Z1]',
    '',
    'Samples the inside test (the IIS ends inside a seed) on a voxel grid and extracts the',
    'surface by marching tetrahedra, each vertex moved onto the surface by bisection. The mesh',
    'is closed and consistently oriented (every edge in exactly two triangles). Graphs with plane',
    'mirrors or generators repeat without end: give --bounds. Progress goes to stderr.',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    const output = stringOption(parsed, 'out');
    if (!output) throw usageError('missing --out MODEL.stl (where to write the mesh)');
    const resText = stringOption(parsed, 'resolution');
    const resolution =
      resText === undefined
        ? DEFAULT_MESH_RESOLUTION
        : parseIntegerOption('resolution', resText, MIN_MESH_RESOLUTION, MAX_MESH_RESOLUTION);
    const boundsText = stringOption(parsed, 'bounds');
    const bounds = boundsText === undefined ? undefined : boundsOption(boundsText);

    const { picture } = await loadAnyScene(io, graphPath);
    if (picture.kind !== '3d') throw new CliError(`${graphPath}: not a 3D graph (it has no render-3d node)`);
    const progress = progressLine(io.stderr, 'meshing');
    const result = await meshScene3d(picture.scene3d, {
      resolution,
      ...(bounds ? { bounds } : {}),
      onProgress: (f) => {
        progress.update(f);
        return true;
      },
    });
    progress.finish();
    if (!result) throw new CliError(`${graphPath}: cancelled`);
    if (!result.ok) throw new CliError(`${graphPath}: no mesh: ${result.error}`);
    const { mesh, grid } = result.value;
    try {
      await io.writeFile(output, writeStl(mesh, `Kleinflow mesh of ${graphPath}`.slice(0, 80)));
    } catch (e) {
      throw new CliError(fileErrorMessage('write', output, e));
    }
    io.stdout.write(
      `wrote ${output} (${mesh.triangles.length / 3} triangles, ${mesh.positions.length / 3} vertices, ${grid.nx}×${grid.ny}×${grid.nz} voxels)\n`,
    );
    return EXIT.ok;
  },
};
