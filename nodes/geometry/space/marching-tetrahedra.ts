/**
 * A closed, consistently oriented triangle mesh of the boundary of a solid given on a voxel grid
 * (docs/math-3d.md "Voxel mesh (paper §5.3.2)"): marching tetrahedra on the Freudenthal split of
 * every cube into six tetrahedra. Each crossing point lies on a grid edge between a solid and an
 * empty sample and is shared by every tetrahedron on that edge, so the surface is watertight; the
 * outermost layer of samples is treated as empty, so it is closed.
 */
import { add3, scale3, sub3, type Vec3 } from './vec3.ts';

export interface Mesh {
  /** x, y, z per vertex. */
  readonly positions: Float64Array;
  /** Three vertex indices per triangle, anticlockwise seen from outside (normal = (b − a) × (c − a) points out). */
  readonly triangles: Uint32Array;
}

/** A grid of (nx + 1)(ny + 1)(nz + 1) samples from `min`, `step` apart along each axis. */
export interface VoxelGrid {
  readonly min: Vec3;
  readonly step: Vec3;
  readonly nx: number;
  readonly ny: number;
  readonly nz: number;
}

/** The position of sample (i, j, k). */
export const gridPoint = (g: VoxelGrid, i: number, j: number, k: number): Vec3 => [
  g.min[0] + i * g.step[0],
  g.min[1] + j * g.step[1],
  g.min[2] + k * g.step[2],
];

/** Index of sample (i, j, k) in a solid-flag array: i fastest. */
export const sampleIndex = (g: VoxelGrid, i: number, j: number, k: number): number =>
  i + (g.nx + 1) * (j + (g.ny + 1) * k);

/** The cube's corners as bits (x = 1, y = 2, z = 4). */
const CORNER: readonly Vec3[] = [0, 1, 2, 3, 4, 5, 6, 7].map((c) => [c & 1, (c >> 1) & 1, (c >> 2) & 1]);

/**
 * The six Freudenthal tetrahedra: for each order of the axes, the path 000 → one axis → two axes →
 * 111. Neighbouring cubes split their shared square along the same diagonal, so the tetrahedra
 * tile the grid. Listed with positive orientation (det(v1 − v0, v2 − v0, v3 − v0) > 0).
 */
const TETS: readonly (readonly [number, number, number, number])[] = (() => {
  const out: [number, number, number, number][] = [];
  for (const [a, b] of [
    [1, 2],
    [1, 4],
    [2, 1],
    [2, 4],
    [4, 1],
    [4, 2],
  ]) {
    const t: [number, number, number, number] = [0, a, a | b, 7];
    const [p0, p1, p2, p3] = t.map((c) => CORNER[c]);
    const u = sub3(p1, p0);
    const v = sub3(p2, p0);
    const w = sub3(p3, p0);
    const det =
      u[0] * (v[1] * w[2] - v[2] * w[1]) -
      u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
    out.push(det > 0 ? t : [t[0], t[1], t[3], t[2]]);
  }
  return out;
})();

/** Even permutations of (0, 1, 2, 3) that start with each index: they keep the orientation. */
const EVEN_FROM: readonly (readonly [number, number, number, number])[] = [
  [0, 1, 2, 3],
  [1, 0, 3, 2],
  [2, 3, 0, 1],
  [3, 2, 1, 0],
];

/** Even permutations (a, b, c, d) of (0, 1, 2, 3) by their first two entries a, b. */
function evenWith(a: number, b: number): [number, number, number, number] {
  const [c, d] = [0, 1, 2, 3].filter((x) => x !== a && x !== b);
  const p: [number, number, number, number] = [a, b, c, d];
  // Parity by counting inversions.
  let inv = 0;
  for (let i = 0; i < 4; i++) for (let j = i + 1; j < 4; j++) if (p[i] > p[j]) inv++;
  return inv % 2 === 0 ? p : [a, b, d, c];
}

export interface MeshOptions {
  /**
   * Where the surface crosses the grid edge from solid sample `inside` to empty sample `outside`:
   * a point between them (default: the midpoint). Bisection with the real inside test puts the
   * vertices on the surface.
   */
  readonly crossing?: (inside: Vec3, outside: Vec3) => Vec3;
  /** Called after each layer of cubes (k of nz); returning false stops with null. */
  readonly onLayer?: (k: number, nz: number) => boolean;
}

/**
 * The mesh of the boundary of {samples with solid[i] = true}, samples on the grid's outer layer
 * counted as empty. Per tetrahedron with s solid corners: none for s = 0 or 4, one triangle around
 * the lone corner for s = 1 or 3, two for s = 2 (a quadrilateral). With the tetrahedron positively
 * oriented and its corners taken in an even order starting at the lone solid corner, the triangle
 * (e01, e02, e03) faces away from it (checked on the unit tetrahedron: (1, 1, 1)).
 */
export function marchingTetrahedra(g: VoxelGrid, solid: Uint8Array, options: MeshOptions = {}): Mesh | null {
  const crossing = options.crossing ?? ((a: Vec3, b: Vec3) => scale3(add3(a, b), 0.5));
  const positions: number[] = [];
  const triangles: number[] = [];
  const vertexOfEdge = new Map<number, number>();
  const total = (g.nx + 1) * (g.ny + 1) * (g.nz + 1);
  const isSolid = (i: number, j: number, k: number) =>
    i > 0 && j > 0 && k > 0 && i < g.nx && j < g.ny && k < g.nz && solid[sampleIndex(g, i, j, k)] === 1;

  const corners: [number, number, number][] = Array.from({ length: 8 }, () => [0, 0, 0]);
  const ids: number[] = new Array(8).fill(0);
  const inside: boolean[] = new Array(8).fill(false);

  /** The vertex on the edge between cube corners a (solid) and b (empty). */
  const vertex = (a: number, b: number): number => {
    const key = ids[a] * total + ids[b];
    const known = vertexOfEdge.get(key);
    if (known !== undefined) return known;
    const [ai, aj, ak] = corners[a];
    const [bi, bj, bk] = corners[b];
    const p = crossing(gridPoint(g, ai, aj, ak), gridPoint(g, bi, bj, bk));
    const index = positions.length / 3;
    positions.push(p[0], p[1], p[2]);
    vertexOfEdge.set(key, index);
    return index;
  };

  for (let k = 0; k < g.nz; k++) {
    for (let j = 0; j < g.ny; j++)
      for (let i = 0; i < g.nx; i++) {
        let count = 0;
        for (let c = 0; c < 8; c++) {
          const [dx, dy, dz] = CORNER[c];
          corners[c] = [i + dx, j + dy, k + dz];
          ids[c] = sampleIndex(g, i + dx, j + dy, k + dz);
          inside[c] = isSolid(i + dx, j + dy, k + dz);
          if (inside[c]) count++;
        }
        if (count === 0 || count === 8) continue;
        for (const tet of TETS) {
          const solidAt = [0, 1, 2, 3].filter((t) => inside[tet[t]]);
          const s = solidAt.length;
          if (s === 0 || s === 4) continue;
          if (s === 1 || s === 3) {
            // The lone corner: solid (s = 1, the triangle faces away from it) or empty (s = 3, towards it).
            const lone = s === 1 ? solidAt[0] : [0, 1, 2, 3].find((t) => !inside[tet[t]])!;
            const [a, b, c, d] = EVEN_FROM[lone].map((t) => tet[t]);
            const e =
              s === 1
                ? [vertex(a, b), vertex(a, c), vertex(a, d)]
                : [vertex(b, a), vertex(d, a), vertex(c, a)];
            triangles.push(e[0], e[1], e[2]);
          } else {
            // Solid a, b and empty c, d in an even order: quad a–c, a–d, b–d, b–c.
            const [a, b, c, d] = evenWith(solidAt[0], solidAt[1]).map((t) => tet[t]);
            const ac = vertex(a, c);
            const ad = vertex(a, d);
            const bd = vertex(b, d);
            const bc = vertex(b, c);
            triangles.push(ac, ad, bd, ac, bd, bc);
          }
        }
      }
    if (options.onLayer && !options.onLayer(k + 1, g.nz)) return null;
  }
  return { positions: Float64Array.from(positions), triangles: Uint32Array.from(triangles) };
}

/** Signed volume of a closed mesh: Σ a·(b × c)/6 over its triangles (positive when it faces out). */
export function meshVolume(m: Mesh): number {
  let v = 0;
  const p = m.positions;
  for (let t = 0; t < m.triangles.length; t += 3) {
    const a = m.triangles[t] * 3;
    const b = m.triangles[t + 1] * 3;
    const c = m.triangles[t + 2] * 3;
    v +=
      p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) -
      p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) +
      p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return v / 6;
}
