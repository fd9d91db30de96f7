/**
 * A 3D scene's solid as a triangle mesh for 3D printing (paper §5.3.2; docs/math-3d.md
 * "Voxel mesh (paper §5.3.2)"): sample the CPU inside test (the IIS ends inside a seed) on a voxel
 * grid over the scene's bounds, then marching tetrahedra with each vertex moved onto the surface
 * by bisection along its grid edge.
 */
import type { Scene3d } from '../../core/scene-3d.ts';
import { sampleSpace } from '../../core/seed-3d.ts';
import {
  gridPoint,
  type Mesh,
  marchingTetrahedra,
  sampleIndex,
  type VoxelGrid,
} from './marching-tetrahedra.ts';
import { fail, ok, type Result, type Sphere } from './sphere.ts';
import { add3, scale3, sub3, type Vec3 } from './vec3.ts';

export interface Bounds3 {
  readonly min: Vec3;
  readonly max: Vec3;
}

export const MIN_MESH_RESOLUTION = 4;
export const MAX_MESH_RESOLUTION = 512;
/** Samples per side of the coarse pass that tightens the bounds. */
const COARSE = 24;

type MeshScene = Pick<Scene3d, 'elements' | 'seeds' | 'maxIterations'>;

/** The CPU inside test: the IIS from p ends inside a seed. */
export const solidAt = (scene: MeshScene, p: Vec3): boolean => {
  const d = sampleSpace(scene, p).distance;
  return d !== null && d < 0;
};

/**
 * A box that holds the whole orbit, or null when none is known: with only sphere inversions every
 * image of a seed lies in the seed or in a mirror's ball, so the box of the seeds and the balls.
 * Plane mirrors and generators repeat the seeds without end: the caller must give bounds.
 */
export function orbitBounds(scene: MeshScene): Bounds3 | null {
  if (scene.seeds.length === 0) return null;
  if (scene.elements.some((e) => e.kind !== 'sphere-inversion')) return null;
  const ballBox = (b: Sphere): [Vec3, Vec3] => [
    sub3(b.center, [b.radius, b.radius, b.radius]),
    add3(b.center, [b.radius, b.radius, b.radius]),
  ];
  const boxes: [Vec3, Vec3][] = scene.seeds.map((s) =>
    s.kind === 'sphere'
      ? ballBox(s.sphere)
      : s.kind === 'tile'
        ? ballBox(s.tile.bound)
        : s.kind === 'formula'
          ? ballBox({ center: s.center, radius: s.radius }) // a solid lies within its bounding ball
          : [sub3(s.center, s.halfSize), add3(s.center, s.halfSize)],
  );
  for (const e of scene.elements)
    if (e.kind === 'sphere-inversion') {
      const r = e.sphere.radius;
      boxes.push([sub3(e.sphere.center, [r, r, r]), add3(e.sphere.center, [r, r, r])]);
    }
  const min = [0, 1, 2].map((a) => Math.min(...boxes.map((b) => b[0][a]))) as unknown as Vec3;
  const max = [0, 1, 2].map((a) => Math.max(...boxes.map((b) => b[1][a]))) as unknown as Vec3;
  return { min, max };
}

/** "X0,Y0,Z0,X1,Y1,Z1" (the CLI's --bounds, the editor's Bounds field) as a box, or why not. */
export function parseBounds(text: string): Result<Bounds3> {
  const v = text.split(',').map((t) => (t.trim() === '' ? Number.NaN : Number(t)));
  if (v.length !== 6 || !v.every(Number.isFinite))
    return fail(`expects six numbers X0,Y0,Z0,X1,Y1,Z1, got "${text}"`);
  const min: Vec3 = [v[0], v[1], v[2]];
  const max: Vec3 = [v[3], v[4], v[5]];
  if (!min.every((m, a) => m < max[a])) return fail('each of X0, Y0, Z0 must be below X1, Y1, Z1');
  const problem = boundsProblem({ min, max });
  return problem ? fail(problem) : ok({ min, max });
}

/**
 * Why a box cannot be meshed, or null: its sides and the grid around it (one cell of padding) must
 * be finite in float64 — `-1e308…1e308` is 2e308 wide, which is ∞, and would mesh as nothing.
 */
export function boundsProblem({ min, max }: Bounds3): string | null {
  const size = sub3(max, min);
  const reach = [...min, ...max].map((v) => Math.abs(v) + Math.max(...size));
  return [...size, ...reach].every(Number.isFinite)
    ? null
    : `the box's extent (${size.map((s) => s.toPrecision(3)).join(' × ')}) is not finite in float64: give a smaller box`;
}

/** A grid with cubic cells, `resolution` of them along the longest side, plus one empty cell of padding all round. */
export function gridFor(bounds: Bounds3, resolution: number): VoxelGrid {
  const size = sub3(bounds.max, bounds.min);
  const step = Math.max(...size) / resolution;
  const cells = size.map((s) => Math.max(1, Math.ceil(s / step - 1e-9)) + 2);
  return {
    min: sub3(bounds.min, [step, step, step]),
    step: [step, step, step],
    nx: cells[0],
    ny: cells[1],
    nz: cells[2],
  };
}

/**
 * The bounds shrunk to the solid found by a coarse pass (COARSE samples per side), widened by one
 * coarse cell and a half so that thin parts between coarse samples are kept; null when the coarse
 * pass finds nothing solid.
 */
export function tightenBounds(scene: MeshScene, bounds: Bounds3): Bounds3 | null {
  const size = sub3(bounds.max, bounds.min);
  const cell = scale3(size, 1 / COARSE);
  let lo: Vec3 | null = null;
  let hi: Vec3 | null = null;
  for (let k = 0; k <= COARSE; k++)
    for (let j = 0; j <= COARSE; j++)
      for (let i = 0; i <= COARSE; i++) {
        const p: Vec3 = add3(bounds.min, [i * cell[0], j * cell[1], k * cell[2]]);
        if (!solidAt(scene, p)) continue;
        lo = lo ? (lo.map((v, a) => Math.min(v, p[a])) as unknown as Vec3) : p;
        hi = hi ? (hi.map((v, a) => Math.max(v, p[a])) as unknown as Vec3) : p;
      }
  if (!lo || !hi) return null;
  const pad = scale3(cell, 1.5);
  const min = sub3(lo, pad).map((v, a) => Math.max(v, bounds.min[a])) as unknown as Vec3;
  const max = add3(hi, pad).map((v, a) => Math.min(v, bounds.max[a])) as unknown as Vec3;
  return { min, max };
}

export interface MeshSceneOptions {
  /** Cells along the longest side of the bounds. */
  readonly resolution: number;
  /** The box to mesh (the solid is cut flat at its sides); default: the orbit's, tightened. */
  readonly bounds?: Bounds3;
  /** Bisection steps per vertex along its grid edge (default 6: 1/64 of a cell). */
  readonly refine?: number;
  /** Fraction done, 0..1; returning false cancels. */
  readonly onProgress?: (fraction: number) => boolean;
  /** Awaited between layers (the editor lets the page breathe). */
  readonly pause?: () => Promise<void>;
}

export interface SceneMesh {
  readonly mesh: Mesh;
  readonly bounds: Bounds3;
  readonly grid: VoxelGrid;
}

/** Share of the progress bar that the sampling takes (the rest is meshing). */
const SAMPLING_SHARE = 0.85;

/** The mesh of the scene's solid; null when cancelled. */
export async function meshScene3d(
  scene: MeshScene,
  options: MeshSceneOptions,
): Promise<Result<SceneMesh> | null> {
  const { resolution } = options;
  if (
    !(Number.isInteger(resolution) && resolution >= MIN_MESH_RESOLUTION && resolution <= MAX_MESH_RESOLUTION)
  )
    return fail(
      `the resolution must be a whole number from ${MIN_MESH_RESOLUTION} to ${MAX_MESH_RESOLUTION}`,
    );
  if (scene.seeds.length === 0) return fail('the scene has no seeds: nothing is solid');
  let bounds = options.bounds;
  if (!bounds) {
    const orbit = orbitBounds(scene);
    if (!orbit)
      return fail('the orbit is unbounded (plane mirrors or generators repeat it without end): give bounds');
    const tight = tightenBounds(scene, orbit);
    if (!tight) return fail('nothing solid was found in the orbit’s bounds');
    bounds = tight;
  }
  if (!bounds.min.every((v, a) => v < bounds.max[a]))
    return fail('the bounds are empty (min must be below max)');
  const problem = boundsProblem(bounds);
  if (problem) return fail(problem);
  const grid = gridFor(bounds, resolution);
  const solid = new Uint8Array((grid.nx + 1) * (grid.ny + 1) * (grid.nz + 1));
  const report = options.onProgress ?? (() => true);
  for (let k = 1; k < grid.nz; k++) {
    for (let j = 1; j < grid.ny; j++)
      for (let i = 1; i < grid.nx; i++)
        if (solidAt(scene, gridPoint(grid, i, j, k))) solid[sampleIndex(grid, i, j, k)] = 1;
    if (!report((SAMPLING_SHARE * k) / grid.nz)) return null;
    if (options.pause) await options.pause();
  }
  const steps = options.refine ?? 6;
  /** Bisection on the segment from a solid point to an empty one; the vertex is the last midpoint. */
  const inBounds = (p: Vec3) => p.every((v, a) => v >= bounds.min[a] && v <= bounds.max[a]);
  const crossing = (inside: Vec3, outside: Vec3): Vec3 => {
    // An edge to the padding layer: the solid is cut there, halfway out of the bounds.
    if (!inBounds(outside)) return scale3(add3(inside, outside), 0.5);
    let a = inside;
    let b = outside;
    for (let s = 0; s < steps; s++) {
      const m = scale3(add3(a, b), 0.5);
      if (solidAt(scene, m)) a = m;
      else b = m;
    }
    return scale3(add3(a, b), 0.5);
  };
  const mesh = marchingTetrahedra(grid, solid, {
    crossing,
    onLayer: (k, nz) => report(SAMPLING_SHARE + ((1 - SAMPLING_SHARE) * k) / nz),
  });
  if (!mesh) return null;
  report(1);
  if (mesh.triangles.length === 0) return fail('nothing solid inside the bounds: the mesh would be empty');
  return ok({ mesh, bounds, grid });
}
