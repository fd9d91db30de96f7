/**
 * `kleinflow mesh GRAPH --out MODEL.stl|.3mf|.glb [--resolution N] [--bounds …] [--print-size MM]`: the solid of a 3D
 * graph (the orbit of its seeds) as a closed triangle mesh for 3D printing (paper §5.3.2; docs/math-3d.md
 * "Voxel mesh (paper §5.3.2)"): binary STL, or with the render's colours per vertex 3MF (full-colour
 * printers) or GLB (viewers) (paper Fig. 36; docs/math-3d.md "Coloured mesh (paper Fig. 36)"), at
 * one scene unit = 1 mm or scaled to a print size (src/io/print-size.ts).
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
  formatPrintSize,
  MAX_PRINT_SIZE_MM,
  MIN_PRINT_SIZE_MM,
  meshExtent,
  millimetresPerUnit,
  parsePrintSize,
} from '../../io/print-size.ts';
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
  {
    long: 'print-size',
    value: 'MM',
    doc: `the model’s longest side in millimetres, ${MIN_PRINT_SIZE_MM}…${MAX_PRINT_SIZE_MM}; default: one scene unit = 1 mm`,
  },
];

/** What a mesh without --print-size is asked to be in the success line's hint. */
const SUGGESTED_PRINT_SIZE = 60;

function boundsOption(text: string): Bounds3 {
  const b = parseBounds(text);
  if (!b.ok) throw usageError(`--bounds ${b.error}`);
  return b.value;
}

function printSizeOption(text: string): number {
  const mm = parsePrintSize(text);
  if (!mm.ok) throw usageError(`--print-size ${mm.error}`);
  return mm.value;
}

/** The success line's tail: the printed size, and how to get a real one when none was asked for. */
function sizeNote(extent: ReturnType<typeof meshExtent>, mmPerUnit: number, asked: boolean, glb: boolean) {
  const size = formatPrintSize(extent, mmPerUnit);
  const hint = asked ? '' : `; --print-size ${SUGGESTED_PRINT_SIZE} for a ${SUGGESTED_PRINT_SIZE} mm print`;
  return `${size}${glb ? ' (in metres in the GLB, glTF’s unit)' : ''}${hint}`;
}

export const meshCommand: CliCommand = {
  name: 'mesh',
  summary: 'write the solid of a 3D graph as a closed mesh: STL, or coloured 3MF / GLB (3D printing)',
  usage: [
    'Usage: kleinflow mesh GRAPH --out MODEL.stl|.3mf|.glb [--resolution N] [--bounds X0,Y0,Z0,X1,Y1,Z1]',
    '                      [--print-size MM]',
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
    'STL and 3MF are in millimetres, GLB in metres (glTF’s unit), all the same physical size: one',
    'scene unit is 1 mm, or --print-size scales the model about the origin so that its longest',
    'side is that many millimetres (--print-size 60: a 60 mm print). The success line says the size.',
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
    const printSizeText = stringOption(parsed, 'print-size');
    const printSize = printSizeText === undefined ? undefined : printSizeOption(printSizeText);

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
    // Scaled only now: the colours above are read at the scene's own coordinates.
    const extent = meshExtent(mesh);
    const mmPerUnit = millimetresPerUnit(extent, printSize);
    const bytes = await meshFileBytes(format, mesh, colours, `Kleinflow mesh of ${graphPath}`, mmPerUnit);
    try {
      await io.writeFile(output, bytes);
    } catch (e) {
      throw new CliError(fileErrorMessage('write', output, e));
    }
    io.stdout.write(
      `wrote ${output} (${mesh.triangles.length / 3} triangles, ${mesh.positions.length / 3} vertices, ${grid.nx}×${grid.ny}×${grid.nz} voxels): ${sizeNote(extent, mmPerUnit, printSize !== undefined, format === 'glb')}\n`,
    );
    return EXIT.ok;
  },
};
