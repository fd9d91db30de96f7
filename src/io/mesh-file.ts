/**
 * The mesh file formats `kleinflow mesh` and Export → Mesh write, chosen by the file's extension:
 * STL (shape only, the printers' oldest format), GLB (vertex colours, for viewers) and 3MF (colour
 * groups, for full-colour printers and slicers). All three carry the same closed triangles
 * (docs/math-3d.md "Voxel mesh (paper §5.3.2)", "Coloured mesh (paper Fig. 36)"), scaled to the
 * same physical size: millimetres in STL and 3MF, metres in GLB (print-size.ts).
 */
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';
import { writeGlb } from './glb.ts';
import { MM_PER_METRE, scaleMesh } from './print-size.ts';
import { writeStl } from './stl.ts';
import { write3mf } from './three-mf.ts';

export type MeshFormat = 'stl' | 'glb' | '3mf';

export interface MeshFormatInfo {
  readonly extension: string;
  readonly mime: string;
  /** What the menu and the dialog call it. */
  readonly label: string;
  /** The file holds the render's colours (they must be computed for it). */
  readonly coloured: boolean;
}

export const MESH_FORMATS: Readonly<Record<MeshFormat, MeshFormatInfo>> = {
  stl: { extension: 'stl', mime: 'model/stl', label: 'STL (shape only)', coloured: false },
  '3mf': { extension: '3mf', mime: 'model/3mf', label: '3MF (full-colour print)', coloured: true },
  glb: {
    extension: 'glb',
    mime: 'model/gltf-binary',
    label: 'GLB (glTF with vertex colours)',
    coloured: true,
  },
};

const FORMAT_NAMES = Object.keys(MESH_FORMATS) as MeshFormat[];

/** The format a file name asks for by its extension (any case), or null. */
export function meshFormatOf(path: string): MeshFormat | null {
  const ext = /\.([^./\\]+)$/.exec(path)?.[1]?.toLowerCase();
  return FORMAT_NAMES.find((f) => f === ext) ?? null;
}

/** The extensions, for messages: ".stl, .3mf or .glb". */
export const MESH_EXTENSIONS = FORMAT_NAMES.map((f) => `.${f}`)
  .join(', ')
  .replace(/, ([^,]+)$/, ' or $1');

/**
 * The file's bytes; `colours` (sRGB per vertex, from shader-gen/space/mesh-colours.ts, read in scene
 * coordinates before this scaling) is needed by the coloured formats and ignored by STL; `title`
 * names the mesh in the file where it can; `mmPerUnit` is the print's millimetres per scene unit
 * (print-size.ts; 1 by default), applied about the origin — divided by 1000 for glTF's metres.
 */
export async function meshFileBytes(
  format: MeshFormat,
  sceneMesh: Mesh,
  colours: Float32Array | null,
  title: string,
  mmPerUnit = 1,
): Promise<Uint8Array<ArrayBuffer>> {
  const mesh = scaleMesh(sceneMesh, format === 'glb' ? mmPerUnit / MM_PER_METRE : mmPerUnit);
  if (format === 'stl') return writeStl(mesh, title.slice(0, 80));
  if (!colours) throw new Error(`a ${format.toUpperCase()} mesh needs its colours`);
  return format === 'glb' ? writeGlb(mesh, colours, title) : write3mf(mesh, colours);
}
