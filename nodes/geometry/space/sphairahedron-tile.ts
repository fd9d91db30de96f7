/**
 * The sphairahedron's tile (paper §5.3, Fig. 25): the lower piece L of the infinite sphairahedron
 * (inside the prism, outside the balls, under a ball), or its image I(L) in the inversion sphere —
 * the finite sphairahedron. Its signed distance is a lower bound of the distance to the solid with
 * the exact sign; derivation and proof: docs/math-3d.md "The tile as a seed".
 *
 *   d_L(q) = max( n_k·a_k − n_k·q   (inside every prism plane F_k: normal n_k into the prism, a_k on it),
 *                 r_k − |q − c_k|   (outside every ball S_k),
 *                 b − q_z           (above the cut b, infinite form only),
 *                 min_k max(|q − c_k|_xy − r_k, q_z − c_k,z) )   (under some ball: its column below the centre)
 *   finite: q = I(p), d(p) = R²·d_L(q) / (|q − O|·(|q − O| + max(d_L, 0)))   (the inversion lemma).
 */
import { invertPlaneToSphere } from './sphairahedron.ts';
import type { InfiniteSphairahedron } from './sphairahedron-shared.ts';
import type { Plane, Sphere } from './sphere.ts';
import { dist3, type Vec3 } from './vec3.ts';

/** Depth of the infinite form's cut below the floor (as the infinite seed box's reach). */
export const TILE_DEPTH = 100;
/** The finite form's cut: far enough below that its image is a speck at the inversion centre. */
export const NO_CUT = -1e9;
/** Most planes (cake: 4) and balls (cube: 3) of a sphairahedron: the GLSL packing's fixed sizes. */
export const TILE_PLANES = 4;
export const TILE_BALLS = 3;
/** Squared distance below which a point counts as the inversion centre (its image is then far). */
const TINY = 1e-24;

export interface SphairahedronTile {
  /** The inversion sphere of the finite form; null for the infinite form. */
  readonly inversion: Sphere | null;
  readonly planes: readonly Plane[];
  readonly balls: readonly Sphere[];
  /** The infinite form's cut z ≥ bottom (NO_CUT for the finite form). */
  readonly bottom: number;
  /** A ball that holds the tile (docs/math-3d.md "The tile as a seed"). */
  readonly bound: Sphere;
}

/** The tile of the infinite sphairahedron, or of its finite form when `inversion` is given. */
export function sphairahedronTile(inf: InfiniteSphairahedron, inversion: Sphere | null): SphairahedronTile {
  const top = Math.max(...inf.spheres.map((s) => s.center[2]));
  const base = { planes: inf.planes, balls: inf.spheres };
  if (!inversion) {
    const bottom = inf.floorTop - TILE_DEPTH;
    const reach = Math.max(...inf.corners.map((c) => Math.hypot(c[0], c[1])));
    const bound = {
      center: [0, 0, (top + bottom) / 2] as Vec3,
      radius: Math.hypot(reach, (top - bottom) / 2),
    };
    return { ...base, inversion: null, bottom, bound };
  }
  return { ...base, inversion, bottom: NO_CUT, bound: finiteBound(inf, inversion) };
}

/**
 * A ball holding I(L): L lies in the union of the columns under the balls, column k in the half-space
 * below c_k,z and in the half-space of the vertical plane touching the column on O's side; the image
 * of whichever of the two does not hold O is a ball (the smaller one is kept), and a ball about their
 * mean centre encloses them all. O outside a column's half-spaces is guaranteed by the centre check.
 */
function finiteBound(inf: InfiniteSphairahedron, inv: Sphere): Sphere {
  const o = inv.center;
  const pieces = inf.spheres.map((s): Sphere => {
    const candidates: Sphere[] = [];
    if (o[2] > s.center[2])
      candidates.push(invertPlaneToSphere(inv, { point: s.center, normal: [0, 0, -1] }));
    const h = Math.hypot(o[0] - s.center[0], o[1] - s.center[1]);
    if (h > s.radius) {
      const u: Vec3 = [(s.center[0] - o[0]) / h, (s.center[1] - o[1]) / h, 0];
      const point: Vec3 = [s.center[0] - u[0] * s.radius, s.center[1] - u[1] * s.radius, 0];
      candidates.push(invertPlaneToSphere(inv, { point, normal: u }));
    }
    // Neither: O is on a column's edge, the image reaches ∞; the inversion sphere's far ball stands in.
    if (candidates.length === 0) return { center: o, radius: Number.MAX_VALUE };
    return candidates.reduce((a, b) => (b.radius < a.radius ? b : a));
  });
  const n = pieces.length;
  const c: Vec3 = [0, 1, 2].map((i) => pieces.reduce((s, p) => s + p.center[i]!, 0) / n) as unknown as Vec3;
  return { center: c, radius: Math.max(...pieces.map((p) => dist3(c, p.center) + p.radius)) };
}

/** d_L at (x, y, z) of the infinite sphairahedron's space (the formula in the header). */
function lowerPieceDistance(t: SphairahedronTile, x: number, y: number, z: number): number {
  let d = t.bottom - z;
  let column = Number.POSITIVE_INFINITY;
  for (const p of t.planes)
    d = Math.max(
      d,
      p.normal[0] * (p.point[0] - x) + p.normal[1] * (p.point[1] - y) + p.normal[2] * (p.point[2] - z),
    );
  for (const s of t.balls) {
    const c = s.center;
    const h = Math.hypot(x - c[0], y - c[1]);
    d = Math.max(d, s.radius - Math.hypot(h, z - c[2]));
    column = Math.min(column, Math.max(h - s.radius, z - c[2]));
  }
  return Math.max(d, column);
}

/** Signed distance bound of the tile at (x, y, z): exact sign, never above the true distance. */
export function tileSignedDistance(t: SphairahedronTile, x: number, y: number, z: number): number {
  const inv = t.inversion;
  if (!inv) return lowerPieceDistance(t, x, y, z);
  const o = inv.center;
  const r2 = inv.radius * inv.radius;
  const dx = x - o[0];
  const dy = y - o[1];
  const dz = z - o[2];
  const far = Math.max(dx * dx + dy * dy + dz * dz, TINY);
  const k = r2 / far;
  const d = lowerPieceDistance(t, o[0] + k * dx, o[1] + k * dy, o[2] + k * dz);
  // |p − O| = √far, |q − O| = R²/√far: R²·d/(|q − O|(|q − O| + d⁺)) = √far·d/(R²/√far + d⁺).
  const f = Math.sqrt(far);
  return (f * d) / (r2 / f + Math.max(d, 0));
}

/** The packing the GLSL twin reads (9 vec4): (O, R or 0), (bottom), 4 planes (n, n·a), 3 balls (c, r), padded. */
export function packTile(t: SphairahedronTile): number[] {
  const inv = t.inversion;
  const out = [...(inv ? [...inv.center, inv.radius] : [0, 0, 0, 0]), t.bottom, 0, 0, 0];
  for (let k = 0; k < TILE_PLANES; k++) {
    const p = t.planes[k];
    // A padding plane never wins the max: its distance is NO_CUT everywhere.
    out.push(
      ...(p
        ? [...p.normal, p.normal[0] * p.point[0] + p.normal[1] * p.point[1] + p.normal[2] * p.point[2]]
        : [0, 0, 0, NO_CUT]),
    );
  }
  for (let k = 0; k < TILE_BALLS; k++) {
    const s = t.balls[k];
    // A padding ball of radius NO_CUT: far outside it (never wins the max), its column never the min.
    out.push(...(s ? [...s.center, s.radius] : [0, 0, 0, NO_CUT]));
  }
  return out;
}
