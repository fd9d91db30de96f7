/**
 * The render's own colours on a mesh of its solid, for full-colour 3D printing (paper §5.3.2,
 * Fig. 36; docs/math-3d.md "Coloured mesh (paper Fig. 36)"). The mesh's vertices lie on the limit
 * surface to 1/64 of a voxel, where the depth of the IIS is as deep as the budget allows and
 * changes from point to point: colouring there gives noise. The renderer sees the surface only to
 * its pixel's size; the print is resolved to one voxel. So each vertex is coloured as a ray would
 * see it at voxel resolution: a short march from two cells out along the vertex normal back
 * towards the vertex (from nearer where that start is on the solid), hit where the seed-image
 * distance is below half a cell, and the walk there
 * (depth, nearest seed, final point) coloured by the Render 3D node's colouring — baseColour, the
 * function the renderer shades with, so every colouring mode is printed as it is drawn. No
 * lighting: the printed object is lit by the room.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';
import { prepareTrace3d } from './plan.ts';
import { baseColour } from './shade-3d.ts';
import { walk3d, walkResult } from './walk.ts';

/** The march starts this many cells out along the normal, and gives up as far beyond the vertex. */
const START_CELLS = 2;
/** Hit tolerance in cells: the surface as the voxel grid resolves it. */
const HIT_CELLS = 0.5;
const MARCH_STEPS = 64;

/** Area-weighted vertex normals n_v = normalize(Σ over v's triangles of (b − a) × (c − a)); 0 where that sum is. */
export function vertexNormals(mesh: Mesh): Float64Array {
  const p = mesh.positions;
  const t = mesh.triangles;
  const n = new Float64Array(p.length);
  for (let i = 0; i < t.length; i += 3) {
    const [a, b, c] = [3 * t[i]!, 3 * t[i + 1]!, 3 * t[i + 2]!];
    const u = [p[b]! - p[a]!, p[b + 1]! - p[a + 1]!, p[b + 2]! - p[a + 2]!];
    const w = [p[c]! - p[a]!, p[c + 1]! - p[a + 1]!, p[c + 2]! - p[a + 2]!];
    const cross = [
      u[1]! * w[2]! - u[2]! * w[1]!,
      u[2]! * w[0]! - u[0]! * w[2]!,
      u[0]! * w[1]! - u[1]! * w[0]!,
    ];
    for (const v of [a, b, c]) for (let k = 0; k < 3; k++) n[v + k]! += cross[k]!;
  }
  for (let v = 0; v < n.length; v += 3) {
    const l = Math.hypot(n[v]!, n[v + 1]!, n[v + 2]!);
    if (l > 0) for (let k = 0; k < 3; k++) n[v + k]! /= l;
  }
  return n;
}

/** Vertices coloured between two progress calls (and pauses). */
const CHUNK = 2048;

export interface MeshColourOptions {
  /** Fraction done, every CHUNK vertices; returning false cancels with null. */
  readonly onProgress?: (done: number) => boolean;
  /** Awaited every CHUNK vertices (the editor lets the page repaint, as meshScene3d does). */
  readonly pause?: () => Promise<void>;
}

/**
 * sRGB r, g, b in [0, 1] per vertex of `mesh` (3 floats a vertex, in the order of its positions);
 * `cell` is the voxel size (the grid's largest step). Null when cancelled.
 */
export async function meshVertexColours(
  scene: Scene3d,
  mesh: Mesh,
  cell: number,
  { onProgress, pause }: MeshColourOptions = {},
): Promise<Float32Array | null> {
  const plan = prepareTrace3d(scene);
  const p = mesh.positions;
  const normals = vertexNormals(mesh);
  const n = p.length / 3;
  const out = new Float32Array(3 * n);
  const w = walkResult();
  const eps = HIT_CELLS * cell;
  const q = [0, 0, 0];
  for (let v = 0; v < n; v++) {
    if (v % CHUNK === 0 && v > 0) {
      if (onProgress?.(v / n) === false) return null;
      await pause?.();
    }
    const o = 3 * v;
    // March q = p + (s − t)·n from t = 0 towards p and a little beyond, from a start s that is
    // off the solid (halved while it is not: another piece may lie within two cells); without
    // such a start, a hit or a normal, the walk from the vertex itself.
    const normal = normals[o] !== 0 || normals[o + 1] !== 0 || normals[o + 2] !== 0;
    let s = START_CELLS * cell;
    const setQ = (along: number) => {
      for (let k = 0; k < 3; k++) q[k] = p[o + k]! + along * normals[o + k]!;
    };
    while (normal && s > eps) {
      setQ(s);
      if (walk3d(plan, q[0]!, q[1]!, q[2]!, false, w).imageDistance >= eps) break;
      s /= 2;
    }
    let t = 0;
    let hit = false;
    for (let i = 0; normal && s > eps && i < MARCH_STEPS && t <= 2 * s; i++) {
      setQ(s - t);
      walk3d(plan, q[0]!, q[1]!, q[2]!, true, w, eps);
      if (w.imageDistance < eps) {
        hit = true;
        break;
      }
      t += Math.max(scene.deScale * w.de, eps / 4);
    }
    if (!hit) {
      setQ(0);
      walk3d(plan, q[0]!, q[1]!, q[2]!, false, w);
    }
    // A scene without seeds has no solid and so no vertices; seed 0 keeps the types total.
    const seed = scene.seeds[Math.max(0, w.seed)]!;
    const c = baseColour(scene.coloring, seed.color, w.depth, [q[0]!, q[1]!, q[2]!], [w.x, w.y, w.z]);
    for (let k = 0; k < 3; k++) out[o + k] = Math.min(1, Math.max(0, c[k]!));
  }
  onProgress?.(1);
  return out;
}
