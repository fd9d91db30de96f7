/**
 * The render's own colours on a mesh of its solid, for full-colour 3D printing (paper §5.3.2,
 * Fig. 36; docs/math-3d.md "Coloured mesh (paper Fig. 36)"): at each vertex the CPU walk gives what
 * the tracer has at a hit there — the depth, the nearest seed, the final point — and the Render 3D
 * node's colouring (baseColour, the same function shadeHit uses, so every colouring mode the
 * renderer has is printed too) turns them into the base colour. No lighting: the printed object is
 * lit by the room.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';
import { prepareTrace3d } from './plan.ts';
import { baseColour } from './shade-3d.ts';
import { walk3d, walkResult } from './walk.ts';

/**
 * sRGB r, g, b in [0, 1] per vertex of `mesh` (3 floats a vertex, in the order of its positions).
 * `onProgress` (fraction done, every few thousand vertices) returning false cancels with null.
 */
export function meshVertexColours(
  scene: Scene3d,
  mesh: Pick<Mesh, 'positions'>,
  onProgress?: (done: number) => boolean,
): Float32Array | null {
  const plan = prepareTrace3d(scene);
  const p = mesh.positions;
  const n = p.length / 3;
  const out = new Float32Array(3 * n);
  const w = walkResult();
  for (let v = 0; v < n; v++) {
    if (onProgress && v % 4096 === 0 && onProgress(v / n) === false) return null;
    const x = p[3 * v]!;
    const y = p[3 * v + 1]!;
    const z = p[3 * v + 2]!;
    walk3d(plan, x, y, z, false, w);
    // A scene without seeds has no solid and so no vertices; seed 0 keeps the types total.
    const seed = scene.seeds[Math.max(0, w.seed)]!;
    const c = baseColour(scene.coloring, seed.color, w.depth, [x, y, z], [w.x, w.y, w.z]);
    for (let k = 0; k < 3; k++) out[3 * v + k] = Math.min(1, Math.max(0, c[k]!));
  }
  onProgress?.(1);
  return out;
}
