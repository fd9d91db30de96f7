/**
 * The Export menu's "STL mesh (3D print)…" item and its dialog (StlExportDialog), kept out of
 * use-document-io.tsx: it adds one menu item and one piece of UI there. The meshing runs on the
 * CPU in layers, letting the page repaint between them so progress shows and Cancel works.
 */
import { type ReactNode, useState } from 'react';
import { meshScene3d } from '../../../nodes/geometry/space/voxel-mesh.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { writeStl } from '../../io/stl.ts';
import type { EditorStore } from '../../state/store.ts';
import { download, fileStem } from '../files.ts';
import type { MenuItem } from '../Menu.tsx';
import { StlExportDialog, type StlExportOptions } from './StlExportDialog.tsx';

interface Options {
  readonly store: EditorStore;
  say(kind: 'ok' | 'error', text: string): void;
}

const nextFrame = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

export function useStlExport({ store, say }: Options): { item: MenuItem; ui: ReactNode } {
  const [open, setOpen] = useState(false);
  const item: MenuItem = {
    label: 'STL mesh (3D print)…',
    hint: '3D graphs, closed mesh',
    onSelect: () => setOpen(true),
  };
  if (!open) return { item, ui: null };
  const run = async (o: StlExportOptions, onProgress: (f: number) => boolean) => {
    const doc = store.getState().doc;
    const scene3d = evaluateGraph(doc, registry).scene3d;
    if (!scene3d) throw new Error('this graph has no Render 3D node: STL export meshes 3D graphs');
    const result = await meshScene3d(scene3d, { ...o, onProgress, pause: nextFrame });
    if (!result) return false;
    if (!result.ok) throw new Error(result.error);
    const { mesh } = result.value;
    const bytes = writeStl(mesh, `Kleinflow mesh of ${fileStem(doc)}`.slice(0, 80));
    download(`${fileStem(doc)}.stl`, bytes, 'model/stl');
    say('ok', `Exported an STL mesh: ${mesh.triangles.length / 3} triangles.`);
    return true;
  };
  return { item, ui: <StlExportDialog run={run} onClose={() => setOpen(false)} /> };
}
