/**
 * The Export menu's "Mesh (3D print)…" item and its dialog (MeshExportDialog), kept out of
 * use-document-io.tsx: it adds one menu item and one piece of UI there. The meshing runs on the
 * CPU in layers, letting the page repaint between them so progress shows and Cancel works; the
 * coloured formats (3MF, GLB) then take the render's colour at every vertex (docs/math-3d.md
 * "Coloured mesh (paper Fig. 36)"); the file is scaled to the print size after that, and the toast
 * says its size in millimetres (src/io/print-size.ts).
 */
import { type ReactNode, useState } from 'react';
import { meshScene3d } from '../../../nodes/geometry/space/voxel-mesh.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { meshVertexColours } from '../../../shader-gen/space/mesh-colours.ts';
import { MESH_FORMATS, meshFileBytes } from '../../io/mesh-file.ts';
import { formatPrintSize, meshExtent, millimetresPerUnit } from '../../io/print-size.ts';
import type { EditorStore } from '../../state/store.ts';
import { download, fileStem } from '../files.ts';
import type { MenuItem } from '../Menu.tsx';
import { MESHING_SHARE, MeshExportDialog, type MeshExportOptions } from './MeshExportDialog.tsx';

interface Options {
  readonly store: EditorStore;
  say(kind: 'ok' | 'error', text: string): void;
}

const nextFrame = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

export function useMeshExport({ store, say }: Options): { item: MenuItem; ui: ReactNode } {
  const [open, setOpen] = useState(false);
  const item: MenuItem = {
    label: 'Mesh (3D print)…',
    hint: '3D graphs: STL, or 3MF / GLB in colour',
    onSelect: () => setOpen(true),
  };
  if (!open) return { item, ui: null };
  const run = async ({ format, printSize, ...o }: MeshExportOptions, onProgress: (f: number) => boolean) => {
    const doc = store.getState().doc;
    const scene3d = evaluateGraph(doc, registry).scene3d;
    if (!scene3d) throw new Error('this graph has no Render 3D node: mesh export meshes 3D graphs');
    const info = MESH_FORMATS[format];
    // The coloured formats: meshing fills the first MESHING_SHARE of the bar, colouring the rest.
    const share = info.coloured ? MESHING_SHARE : 1;
    const result = await meshScene3d(scene3d, {
      ...o,
      onProgress: (f) => onProgress(f * share),
      pause: nextFrame,
    });
    if (!result) return false;
    if (!result.ok) throw new Error(result.error);
    const { mesh, grid } = result.value;
    let colours: Float32Array | null = null;
    if (info.coloured) {
      colours = await meshVertexColours(scene3d, mesh, Math.max(...grid.step), {
        onProgress: (f) => onProgress(share + f * (1 - share)),
        pause: nextFrame,
      });
      if (!colours) return false;
    }
    // Scaled only now: the colours are read at the scene's own coordinates.
    const extent = meshExtent(mesh);
    const mmPerUnit = millimetresPerUnit(extent, printSize);
    const bytes = await meshFileBytes(format, mesh, colours, `Kleinflow mesh of ${fileStem(doc)}`, mmPerUnit);
    download(`${fileStem(doc)}.${info.extension}`, bytes, info.mime);
    const hint = printSize === undefined ? ' (one unit = 1 mm: set Print size for a real print)' : '';
    say(
      'ok',
      `Exported a ${format.toUpperCase()} mesh: ${mesh.triangles.length / 3} triangles, ${formatPrintSize(extent, mmPerUnit)}${hint}.`,
    );
    return true;
  };
  return { item, ui: <MeshExportDialog run={run} onClose={() => setOpen(false)} /> };
}
