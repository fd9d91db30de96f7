/**
 * A small coloured mesh for the GLB and 3MF tests: a seed sphere (radius 0.7 at the origin) and its
 * image in one inversion sphere (centre (2, 0, 0), radius 1.25), which lies at 0.80 ≤ x ≤ 1.42 —
 * coloured by depth on the colour wheel, so the seed's vertices have the seed's colour and the
 * image's the colour a quarter turn on; and a check that a mesh is closed and oriented.
 */
import type { Mesh } from '../../../nodes/geometry/space/marching-tetrahedra.ts';
import { meshScene3d } from '../../../nodes/geometry/space/voxel-mesh.ts';
import { hsvToRgb } from '../../../shader-gen/colour.ts';
import { meshVertexColours } from '../../../shader-gen/space/mesh-colours.ts';
import { rgbToHsv } from '../../../shader-gen/space/shade-3d.ts';
import type { Rgb } from '../../../shader-gen/srgb.ts';
import { scene3d, seedSphere } from './scenes-3d.ts';

export const SEED_COLOUR: Rgb = [0.9, 0.35, 0.2];
/** The seed colour turned a quarter of the wheel: the image's colour (depth 1). */
export const IMAGE_COLOUR: Rgb = (() => {
  const [h, s, v] = rgbToHsv(SEED_COLOUR);
  return hsvToRgb(h + 0.25, s, v);
})();
/** Seed vertices lie at x ≤ 0.7, image vertices at x ≥ 0.8 (up to the grid's bisection error). */
export const SEED_SIDE_X = 0.75;

export const TWO_SPHERES = scene3d(
  [{ kind: 'sphere-inversion', sphere: { center: [2, 0, 0], radius: 1.25 } }],
  [seedSphere([0, 0, 0], 0.7, SEED_COLOUR)],
  { coloring: { mode: 'depth-wheel', step: 0.25 } },
);

/** The two spheres meshed at `resolution`, with their sRGB vertex colours. */
export async function colouredMesh(
  resolution = 20,
): Promise<{ mesh: Mesh; colours: Float32Array; cell: number }> {
  const result = await meshScene3d(TWO_SPHERES, { resolution });
  if (!result?.ok) throw new Error(`no mesh: ${result ? result.error : 'cancelled'}`);
  const cell = Math.max(...result.value.grid.step);
  const colours = await meshVertexColours(TWO_SPHERES, result.value.mesh, cell);
  if (!colours) throw new Error('colouring cancelled');
  return { mesh: result.value.mesh, colours, cell };
}

/**
 * Directed edges (a → b of every triangle) that are not matched by exactly one b → a, and not
 * unique: 0 for a closed, consistently oriented mesh (every edge in exactly two triangles, walked
 * once each way).
 */
export function unmatchedEdges(triangles: ArrayLike<number>): number {
  const directed = new Map<string, number>();
  for (let t = 0; t < triangles.length; t += 3)
    for (let e = 0; e < 3; e++) {
      const k = `${triangles[t + e]}>${triangles[t + ((e + 1) % 3)]}`;
      directed.set(k, (directed.get(k) ?? 0) + 1);
    }
  let bad = 0;
  for (const [k, n] of directed) {
    const [a, b] = k.split('>');
    if (n !== 1 || directed.get(`${b}>${a}`) !== 1) bad++;
  }
  return bad;
}
