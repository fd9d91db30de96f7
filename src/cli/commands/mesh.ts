/**
 * `kleinflow mesh GRAPH --out MODEL.stl|.3mf|.glb [--resolution N] [--bounds …]`: the solid of a 3D
 * graph (the orbit of its seeds) as a closed triangle mesh for 3D printing (paper §5.3.2; docs/math-3d.md
 * "Voxel mesh (paper §5.3.2)"): binary STL, or with the render's colours per vertex 3MF (full-colour
 * printers) or GLB (viewers) (paper Fig. 36; docs/math-3d.md "Coloured mesh (paper Fig. 36)").
 */
import {
  type Bounds3,
  MAX_MESH_RESOLUTION,
  MIN_MESH_RESOLUTION,
  meshScene3d,
  parseBounds,
} from '../../../nodes/geometry/space/voxel-mesh.ts';
import { meshVertexColours } from '../../../shader-gen/space/mesh-colours.ts';
import { MESH_EXTENSIONS, MESH_FORMATS, meshFileBytes, meshFormatOf } from '../../io/mesh-file.ts';
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
  {
    long: 'out',
    short: 'o',
    value: 'FILE',
    doc: `the file to write (required): ${MESH_EXTENSIONS}, chosen by its extension`,
  },
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
  summary: 'write the solid of a 3D graph as a closed mesh: STL, or coloured 3MF / GLB (3D printing)',
  usage: [
    'Usage: kleinflow mesh GRAPH --out MODEL.stl|.3mf|.glb [--resolution N] [--bounds X0,Y0,Z0,X1,Y1,Z1]',
    '',
    'Samples the inside test (the IIS ends inside a seed) on a voxel grid and extracts the',
    'surface by marching tetrahedra, each vertex moved onto the surface by bisection. The mesh',
    'is closed and consistently oriented (every edge in exactly two triangles). Graphs with plane',
    'mirrors or generators repeat without end: give --bounds. Progress goes to stderr.',
    '',
    'The extension picks the format: .stl (shape only), .3mf (full-colour printers and slicers:',
    'a colour group, each triangle naming its corners’ colours) or .glb (glTF, COLOR_0 per vertex,',
    'for viewers). The colours are the Render 3D node’s colouring at each vertex, without lighting.',
    '',
    formatOptions(OPTIONS),
  ].join('\n'),
  async run(args, io) {
    const parsed = parseArgs(args, OPTIONS);
    const [graphPath] = expectPositionals(parsed, ['GRAPH']);
    const output = stringOption(parsed, 'out');
    if (!output) throw usageError('missing --out MODEL.stl (where to write the mesh)');
    const format = meshFormatOf(output);
    if (!format) throw usageError(`--out ${output}: the file must end in ${MESH_EXTENSIONS} (the format)`);
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
    let colours: Float32Array | null = null;
    if (MESH_FORMATS[format].coloured) {
      const colouring = progressLine(io.stderr, 'colouring');
      colours = await meshVertexColours(picture.scene3d, mesh, Math.max(...grid.step), {
        onProgress: (f) => {
          colouring.update(f);
          return true;
        },
      });
      colouring.finish();
    }
    const bytes = await meshFileBytes(format, mesh, colours, `Kleinflow mesh of ${graphPath}`);
    try {
      await io.writeFile(output, bytes);
    } catch (e) {
      throw new CliError(fileErrorMessage('write', output, e));
    }
    io.stdout.write(
      `wrote ${output} (${mesh.triangles.length / 3} triangles, ${mesh.positions.length / 3} vertices, ${grid.nx}×${grid.ny}×${grid.nz} voxels)\n`,
    );
    return EXIT.ok;
  },
};
