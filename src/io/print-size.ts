/**
 * The physical size of an exported mesh (docs/math-3d.md "Coloured mesh (paper Fig. 36)", its
 * "Print size"): STL and 3MF are in millimetres, and without a print size one scene unit is 1 mm —
 * the Fig. 36 quasi-sphere is then a 1.5 mm speck. A print size S (mm) is the model's longest side:
 * every vertex p becomes s·p with s = S / max(size_x, size_y, size_z), the size taken from the
 * mesh's own bounding box. The scaling is about the origin: a uniform linear map, so the mesh stays
 * closed and oriented, and the scene's origin (where its ground and centre are) stays the file's.
 * glTF's unit is the metre (glTF 2.0, "Coordinate System and Units"): the GLB gets s / 1000, the
 * same physical size.
 */
import type { Mesh } from '../../nodes/geometry/space/marching-tetrahedra.ts';
import { fail, ok, type Result } from '../../nodes/geometry/space/sphere.ts';
import type { Vec3 } from '../../nodes/geometry/space/vec3.ts';

/** The smallest print size: below a millimetre no printer draws a shape. */
export const MIN_PRINT_SIZE_MM = 1;
/** The largest: 10 m, beyond any printer's build volume (a larger value is a typo). */
export const MAX_PRINT_SIZE_MM = 10_000;
/** Millimetres in glTF's unit, the metre. */
export const MM_PER_METRE = 1000;

/** The mesh's bounding-box size along x, y and z (scene units). */
export function meshExtent({ positions: p }: Mesh): Vec3 {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < p.length; i += 3)
    for (let a = 0; a < 3; a++) {
      lo[a] = Math.min(lo[a]!, p[i + a]!);
      hi[a] = Math.max(hi[a]!, p[i + a]!);
    }
  return [hi[0]! - lo[0]!, hi[1]! - lo[1]!, hi[2]! - lo[2]!];
}

/**
 * Millimetres per scene unit: printSize / (the longest side of `extent`), or 1 (one unit is 1 mm)
 * without a print size. Throws on a mesh with no extent (it has no size to scale).
 */
export function millimetresPerUnit(extent: Vec3, printSize?: number): number {
  if (printSize === undefined) return 1;
  const longest = Math.max(...extent);
  if (!(longest > 0 && Number.isFinite(longest))) throw new Error('the mesh has no size to scale');
  return printSize / longest;
}

/** The mesh with every vertex p moved to factor·p (the triangles are shared: they do not change). */
export function scaleMesh(mesh: Mesh, factor: number): Mesh {
  if (factor === 1) return mesh;
  return { positions: mesh.positions.map((v) => v * factor), triangles: mesh.triangles };
}

/**
 * A print size as typed ("60", "60.5", "60 mm"), in [MIN_PRINT_SIZE_MM, MAX_PRINT_SIZE_MM], or why
 * not (the CLI's --print-size, the dialog's Print size field).
 */
export function parsePrintSize(text: string): Result<number> {
  const m = /^\s*(\d+(?:\.\d*)?|\.\d+)\s*(?:mm)?\s*$/i.exec(text);
  if (!m) return fail(`expects the longest side in millimetres, such as 60, got "${text}"`);
  const mm = Number(m[1]);
  if (mm < MIN_PRINT_SIZE_MM || mm > MAX_PRINT_SIZE_MM)
    return fail(`must be between ${MIN_PRINT_SIZE_MM} and ${MAX_PRINT_SIZE_MM} mm, got ${mm}`);
  return ok(mm);
}

/** One length for people: a tenth of a millimetre, or two significant digits below 1 mm. */
const mmText = (v: number) => (v < 0.95 ? String(Number(v.toPrecision(2))) : v.toFixed(1));

/** "1.5 × 1.6 × 1.6 mm": the size of a mesh of `extent` (scene units) at `mmPerUnit`. */
export function formatPrintSize(extent: Vec3, mmPerUnit: number): string {
  return `${extent.map((v) => mmText(v * mmPerUnit)).join(' × ')} mm`;
}
