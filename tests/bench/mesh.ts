/**
 * STL mesh export speed (docs/math-3d.md "Voxel mesh (paper §5.3.2)"): the 3D examples with a
 * bounded orbit meshed at a few resolutions on one core — voxels sampled per second (the IIS inside
 * test dominates) and the whole export's time, triangle count and volume sign; then the seconds the
 * coloured formats add to colour the vertices (docs/math-3d.md "Coloured mesh (paper Fig. 36)").
 */
import { readFileSync } from 'node:fs';
import { meshVolume } from '../../nodes/geometry/space/marching-tetrahedra.ts';
import { meshScene3d, orbitBounds } from '../../nodes/geometry/space/voxel-mesh.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { meshVertexColours } from '../../shader-gen/space/mesh-colours.ts';
import { EXAMPLES_3D_DIR, exampleNames, examplePath } from '../../src/cli/examples.ts';
import { printTable } from './report.ts';

const RESOLUTIONS = [32, 64] as const;

export async function run(): Promise<void> {
  console.log('\nSTL mesh export (one core: voxel sampling + marching tetrahedra + bisection)');
  const rows: string[][] = [];
  for (const name of exampleNames(EXAMPLES_3D_DIR)) {
    const loaded = parseDocumentText(readFileSync(examplePath(name, EXAMPLES_3D_DIR), 'utf8'), registry);
    if (!loaded.ok) continue;
    const scene = evaluateGraph(loaded.doc, registry).scene3d;
    if (!scene || !orbitBounds(scene)) continue;
    for (const resolution of RESOLUTIONS) {
      const t0 = performance.now();
      const r = await meshScene3d(scene, { resolution });
      const seconds = (performance.now() - t0) / 1000;
      if (!r?.ok) {
        rows.push([name, String(resolution), r ? r.error : 'cancelled', '', '', '', '']);
        continue;
      }
      const { grid, mesh } = r.value;
      const c0 = performance.now();
      await meshVertexColours(scene, mesh, Math.max(...grid.step));
      const colourSeconds = (performance.now() - c0) / 1000;
      const voxels = (grid.nx + 1) * (grid.ny + 1) * (grid.nz + 1);
      rows.push([
        name,
        String(resolution),
        `${Math.round(voxels / seconds).toLocaleString('en')}`,
        seconds.toFixed(2),
        String(mesh.triangles.length / 3),
        meshVolume(mesh) > 0 ? '+' : '−',
        colourSeconds.toFixed(2),
      ]);
    }
  }
  printTable(['example', 'N', 'voxels/s', 's', 'triangles', 'vol', 'colour s'], rows);
}
