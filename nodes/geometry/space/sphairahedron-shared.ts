/**
 * What every infinite sphairahedron shares, whatever its prism (docs/math-3d.md "Sphairahedra
 * (paper §5.3)"): the shape record and the floor ("initial hyperplane") under the upper piece.
 */
import type { SphairahedronType } from './sphairahedron-types.ts';
import { fail, ok, type Plane, planeSignedDistance, type Result, type Sphere } from './sphere.ts';
import { add3, cross3, dist3, scale3, sub3, type Vec3, vec3 } from './vec3.ts';

/**
 * Why a shape whose faces all exist is outside the parameter space. A stray edge: a sphere crosses
 * a plane it has no edge with (an angle that is not π/n), its ball overlapping its own mirror
 * image — facing the open side (bridge: the tiling spans it) or under the balls (tunnel: the
 * tiling cuts through the solid). A hole: the spheres leave a gap in the prism's floor, so the
 * upper and lower pieces of the complement join (tunnel).
 */
export type OutsideSpace =
  | { readonly kind: 'bridge' | 'tunnel'; readonly sphere: string; readonly plane: string }
  | { readonly kind: 'hole' };

/**
 * The prism's corners lie in the plane z = 0. Cube type: the spheres S1, S2, S3 sit at heights 0,
 * zb, zc. Pentahedral prism: the corner sphere S_c at height 0, the central S_m at zb. Cake: S1 at
 * 0, S2 at zb.
 */
export interface InfiniteSphairahedron {
  readonly type: SphairahedronType;
  /** The cross-section's corners (anticlockwise, z = 0): V1, V2, V3 of the triangle, or the rectangle's four. */
  readonly corners: readonly Vec3[];
  /** The vertical planes F1, F2, …, each normal pointing into the prism (the kept side). */
  readonly planes: readonly Plane[];
  /** Cube type: S1, S2, S3, S_k in corner V_k. Pentahedral prism: S_c (corner V1), then S_m. Cake: S1, S2. */
  readonly spheres: readonly Sphere[];
  /**
   * Height of the "initial hyperplane": inside the prism, every point below it that is outside the
   * balls belongs to the lower piece of the complement (the far side of the quasi-sphere).
   */
  readonly floorTop: number;
  /**
   * Why the shape is outside its type's parameter space while its faces still exist (bridges,
   * tunnels: sphairahedron-space.ts); empty inside it.
   */
  readonly outside: readonly OutsideSpace[];
}

/** Where the top of ball s is above the horizontal point (x, y), or −∞ when it is not above it. */
export function ballTop(s: Sphere, x: number, y: number): number {
  const h2 = (x - s.center[0]) ** 2 + (y - s.center[1]) ** 2;
  return h2 < s.radius * s.radius ? s.center[2] + Math.sqrt(s.radius * s.radius - h2) : -Infinity;
}

/** Samples per fan triangle side for the floor check; the floor's height is lowered by FLOOR_MARGIN. */
const FLOOR_SAMPLES = 64;
export const FLOOR_MARGIN = 0.02;

/** The floor's height, and whether the spheres leave a hole in the prism's floor (a tunnel). */
export interface Floor {
  readonly top: number;
  readonly hole: boolean;
}

/**
 * The floor: over every point of the (convex) cross-section, sampled on a barycentric grid in each
 * triangle of the fan from its centroid, the highest ball top; its minimum is the lowest point of
 * the upper piece, where the initial hyperplane goes (less a margin). A sampled point that no ball
 * covers is a hole in the prism's floor: the two pieces join there (a tunnel, outside the
 * parameter space); the floor is then the lowest top over the covered points. No covered point at
 * all: the spheres do not close the prism (degenerate).
 */
export function floorTop(corners: readonly Vec3[], spheres: readonly Sphere[]): Result<Floor> {
  const m = corners.length;
  const g = vec3(corners.reduce((s, c) => s + c[0], 0) / m, corners.reduce((s, c) => s + c[1], 0) / m, 0);
  let lowest = Infinity;
  let hole = false;
  const n = FLOOR_SAMPLES;
  for (let k = 0; k < m; k++) {
    const a = corners[k];
    const b = corners[(k + 1) % m];
    for (let i = 0; i <= n; i++)
      for (let j = 0; i + j <= n; j++) {
        // Barycentric samples pulled 1% towards the centroid: the corners and sides are ideal
        // points where a ball only touches.
        const u = (0.99 * i) / n;
        const v = (0.99 * j) / n;
        const w = 1 - u - v;
        const x = u * a[0] + v * b[0] + w * g[0];
        const y = u * a[1] + v * b[1] + w * g[1];
        // A loop, not Math.max over a mapped array: the parameter-space view calls this per pixel.
        let top = -Infinity;
        for (const s of spheres) top = Math.max(top, ballTop(s, x, y));
        if (top === -Infinity) hole = true;
        else lowest = Math.min(lowest, top);
      }
  }
  if (lowest === Infinity) return fail('the spheres do not close the prism: no sphere covers its floor');
  return ok({ top: lowest - FLOOR_MARGIN, hole });
}

/** Points per circle for the stray-edge check. */
const CIRCLE_SAMPLES = 96;

/**
 * The stray edge of sphere `k` meeting plane `plane` (which is not one of its faces' neighbours in
 * the type), or null. The circle where they meet is harmless when every point of it that lies in
 * the prism is inside another ball (it is then no part of the sphairahedron's surface); otherwise
 * it is an edge the type does not have, at an angle that is not π/n: the ball pokes through the
 * plane and overlaps its own mirror image. Where the edge faces the sky (a visible point on the
 * ball's upper half with no other ball above it: the upper piece U, the open side) the overlap
 * spans the open side — a bridge; where it lies under the balls (the lower piece L, the solid
 * side) it cuts through the solid — a tunnel (docs/math-3d.md "The parameter space: bridges and
 * tunnels").
 */
export function strayEdge(
  planes: readonly Plane[],
  spheres: readonly Sphere[],
  k: number,
  plane: number,
  sphereName = `S${k + 1}`,
): OutsideSpace | null {
  const s = spheres[k];
  const p = planes[plane];
  const h = planeSignedDistance(p, s.center);
  if (Math.abs(h) >= s.radius) return null;
  const rho = Math.sqrt(s.radius * s.radius - h * h);
  const foot = sub3(s.center, scale3(p.normal, h));
  // Two unit vectors spanning the plane (its normal is horizontal: the vertical is one of them).
  const u: Vec3 = [0, 0, 1];
  const v = cross3(p.normal, u);
  let upper = false;
  let lower = false;
  for (let i = 0; i < CIRCLE_SAMPLES; i++) {
    const a = (2 * Math.PI * i) / CIRCLE_SAMPLES;
    const q = add3(foot, add3(scale3(u, rho * Math.cos(a)), scale3(v, rho * Math.sin(a))));
    const inPrism = planes.every((pl, j) => j === plane || planeSignedDistance(pl, q) > -1e-9);
    const covered = spheres.some((o, j) => j !== k && dist3(q, o.center) < o.radius);
    if (!inPrism || covered) continue;
    const open = q[2] >= s.center[2] && spheres.every((o, j) => j === k || ballTop(o, q[0], q[1]) < q[2]);
    if (open) upper = true;
    else lower = true;
  }
  if (!upper && !lower) return null;
  return { kind: upper ? 'bridge' : 'tunnel', sphere: sphereName, plane: `F${plane + 1}` };
}
