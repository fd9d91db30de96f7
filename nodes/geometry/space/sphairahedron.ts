/**
 * Sphairahedra (paper §5.3, Figs. 25–29): the infinite one (a prism of vertical planes closed
 * below by spheres, a vertex at infinity) from the shape parameters — cube types and pentahedral
 * prisms here, cakes in sphairahedron-cake.ts — and the finite one (its faces inverted in a sphere
 * whose centre lies in the infinite one). The formulas and where they come from: docs/math-3d.md
 * "Sphairahedra (paper §5.3)".
 */
import type { Element3d } from './iis-3d.ts';
import { infiniteCake } from './sphairahedron-cake.ts';
import { ballTop, type InfiniteSphairahedron, strayEdge } from './sphairahedron-shared.ts';
import { withOutside } from './sphairahedron-space.ts';
import {
  CAKE_TYPES,
  CUBE_TYPES,
  type CubeTypeAngles,
  type PentahedralPrismAngles,
  SPHAIRAHEDRON_TYPES,
  type SphairahedronType,
} from './sphairahedron-types.ts';
import {
  fail,
  invertSphere,
  ok,
  type Plane,
  planeSignedDistance,
  type Result,
  type Sphere,
} from './sphere.ts';
import { add3, dist3, dot3, scale3, sub3, type Vec3 } from './vec3.ts';

export type { InfiniteSphairahedron } from './sphairahedron-shared.ts';
export { FLOOR_MARGIN } from './sphairahedron-shared.ts';
export type {
  CakeAngles,
  CubeTypeAngles,
  PentahedralPrismAngles,
  SphairahedronType,
} from './sphairahedron-types.ts';

export interface FiniteSphairahedron {
  /** The faces: images of F1, F2, F3, then of the spheres. Each region is the ball. */
  readonly spheres: readonly Sphere[];
  /** The image of the half-space below the initial hyperplane: a ball, the orbit seed. */
  readonly seed: Sphere;
}

const idx = (k: number) => ((k % 3) + 3) % 3;
const unit2 = (x: number, y: number): Vec3 => {
  const l = Math.hypot(x, y);
  return [x / l, y / l, 0];
};

/** Corners on the unit circle with angles π/p_k: the arc V_k → V_{k+1} subtends 2π/p_{k+2}. */
function prismCorners(p: readonly [number, number, number]): [Vec3, Vec3, Vec3] {
  const a1 = 0;
  const a2 = a1 + (2 * Math.PI) / p[2];
  const a3 = a2 + (2 * Math.PI) / p[0];
  const at = (a: number): Vec3 => [Math.cos(a), Math.sin(a), 0];
  return [at(a1), at(a2), at(a3)];
}

/** F_k through V_{k+1} and V_{k+2}, unit normal pointing towards V_k. */
function prismPlanes(v: readonly [Vec3, Vec3, Vec3]): [Plane, Plane, Plane] {
  return [0, 1, 2].map((k) => {
    const a = v[idx(k + 1)];
    const b = v[idx(k + 2)];
    let n = unit2(-(b[1] - a[1]), b[0] - a[0]);
    if (dot3(sub3(v[k], a), n) < 0) n = scale3(n, -1);
    return { point: a, normal: n };
  }) as [Plane, Plane, Plane];
}

/**
 * w_k: the horizontal unit direction from V_k to the centre of S_k per unit radius. A sphere meeting
 * a plane (inward normal n) at interior angle θ has its centre at signed distance r·cos θ from it,
 * so n_{k+1}·w = cos β₁ and n_{k+2}·w = cos β₂ (a 2 × 2 solve). |w_k| = 1 because the vertex on
 * the edge through V_k is ideal (the sphere touches that edge line).
 */
function cornerDirection(planes: readonly Plane[], k: number, beta: readonly [number, number]): Vec3 {
  const n1 = planes[idx(k + 1)].normal;
  const n2 = planes[idx(k + 2)].normal;
  const c1 = Math.cos(Math.PI / beta[0]);
  const c2 = Math.cos(Math.PI / beta[1]);
  const det = n1[0] * n2[1] - n1[1] * n2[0];
  return [(c1 * n2[1] - c2 * n1[1]) / det, (n1[0] * c2 - n2[0] * c1) / det, 0];
}

/** Solves the 3 × 3 system m·x = b by Cramer's rule; null when singular. */
function solve3(m: readonly Vec3[], b: Vec3): Vec3 | null {
  const det = (a: Vec3, c: Vec3, d: Vec3) =>
    a[0] * (c[1] * d[2] - c[2] * d[1]) -
    a[1] * (c[0] * d[2] - c[2] * d[0]) +
    a[2] * (c[0] * d[1] - c[1] * d[0]);
  const d = det(m[0], m[1], m[2]);
  if (Math.abs(d) < 1e-12) return null;
  const col = (j: number): Vec3[] =>
    m.map((row, i) => row.map((v, c) => (c === j ? b[i] : v)) as unknown as Vec3);
  return [0, 1, 2].map((j) => {
    const [r0, r1, r2] = col(j);
    return det(r0, r1, r2) / d;
  }) as unknown as Vec3;
}

/**
 * The infinite sphairahedron of a type: cube (shape parameters zb, zc), pentahedral prism or cake
 * (zb; zc unused). Cube type, with zb, zc (the heights of S2 and S3;
 * S1 is at height 0). Centres c_k = V_k + r_k·w_k + z_k·e_z; the sphere–sphere angles give, for each
 * pair (i, j) with ΔV = V_i − V_j, the linear equation
 *   2 r_i (ΔV·w_i) − 2 r_j (ΔV·w_j) = −|ΔV|² − (z_i − z_j)²
 * (the terms in r² cancel because the vertices are ideal), solved for r_1, r_2, r_3.
 */
export function infiniteSphairahedron(
  type: SphairahedronType,
  zb: number,
  zc: number,
): Result<InfiniteSphairahedron> {
  if (!Number.isFinite(zb) || !Number.isFinite(zc))
    return fail('the shape parameters must be finite numbers');
  return type.kind === 'cube'
    ? infiniteCube(type, zb, zc)
    : type.kind === 'cake'
      ? infiniteCake(type, zb)
      : infinitePentahedralPrism(type, zb);
}

function infiniteCube(type: CubeTypeAngles, zb: number, zc: number): Result<InfiniteSphairahedron> {
  const corners = prismCorners(type.prism);
  const planes = prismPlanes(corners);
  const w = [0, 1, 2].map((k) => cornerDirection(planes, k, type.spherePlane[k]));
  const z: Vec3 = [0, zb, zc];
  const rows: Vec3[] = [];
  const rhs: number[] = [];
  for (const [i, j] of [
    [0, 1],
    [1, 2],
    [2, 0],
  ]) {
    const dv = sub3(corners[i], corners[j]);
    const row: [number, number, number] = [0, 0, 0];
    row[i] = 2 * dot3(dv, w[i]);
    row[j] = -2 * dot3(dv, w[j]);
    rows.push(row);
    rhs.push(-dot3(dv, dv) - (z[i] - z[j]) ** 2);
  }
  const r = solve3(rows, rhs as unknown as Vec3);
  if (!r) return fail('the sphere radii are not determined for this type (singular system)');
  const names = ['S1', 'S2', 'S3'];
  for (let k = 0; k < 3; k++)
    if (!(r[k] > 1e-6))
      return fail(
        `sphere ${names[k]} would need a radius ≤ 0: zb, zc are outside this type's parameter space, where no shape exists`,
      );
  const spheres = [0, 1, 2].map((k) => ({
    center: add3(add3(corners[k], scale3(w[k], r[k])), [0, 0, z[k]]),
    radius: r[k],
  })) as [Sphere, Sphere, Sphere];
  const bridges = [0, 1, 2].map((k) => strayEdge(planes, spheres, k, k));
  return withOutside({ type, corners, planes, spheres }, bridges);
}

/**
 * The infinite pentahedral prism: the central sphere S_m at distance r·cos(π/m_i) from every plane
 * F_i is a 3 × 3 linear system in its horizontal centre and radius,
 *   n_i·(x, y) − r cos(π/m_i) = n_i·q_i   (i = 1, 2, 3),
 * so its radius is fixed by the prism; it sits at height zb. The corner sphere S_c in V1 has centre
 * V1 + r_c w_1 (as for the cube) at height 0, and the angle γ with S_m gives, with Δ = V1 − c_m
 * (horizontal) and |w_1| = 1,  r_c (2Δ·w_1 − 2 r_m cos γ) = r_m² − |Δ|² − zb².
 */
function infinitePentahedralPrism(type: PentahedralPrismAngles, zb: number): Result<InfiniteSphairahedron> {
  const corners = prismCorners(type.prism);
  const planes = prismPlanes(corners);
  const rows = planes.map((p, i): Vec3 => [p.normal[0], p.normal[1], -Math.cos(Math.PI / type.central[i])]);
  const rhs = planes.map((p) => dot3(p.normal, p.point)) as unknown as Vec3;
  const central = solve3(rows, rhs);
  if (!central || !(central[2] > 1e-6)) return fail('the central sphere is not determined for this type');
  const rm = central[2];
  const cm: Vec3 = [central[0], central[1], zb];
  const w = cornerDirection(planes, 0, type.corner);
  const delta = sub3(corners[0], [cm[0], cm[1], 0]);
  const a = 2 * dot3(delta, w) - 2 * rm * Math.cos(Math.PI / type.sphereSphere);
  const rc = Math.abs(a) < 1e-12 ? Number.NaN : (rm * rm - dot3(delta, delta) - zb * zb) / a;
  if (!(rc > 1e-6))
    return fail(
      'the corner sphere would need a radius ≤ 0: zb is outside this type’s parameter space, where no shape exists',
    );
  const corner: Sphere = { center: add3(corners[0], scale3(w, rc)), radius: rc };
  const spheres = [corner, { center: cm, radius: rm }];
  return withOutside({ type, corners, planes, spheres }, [strayEdge(planes, spheres, 0, 0, 'S_c')]);
}

/** Relative margin that keeps the inversion centre visibly away from the faces. */
const CENTRE_MARGIN = 1e-6;

/**
 * Why the inversion centre O cannot be used, or null. O must lie in the upper piece of the infinite
 * sphairahedron: inside the prism (else that plane's image would keep the wrong side: a face turned
 * inside out), outside every ball (likewise), and under the open sky — the vertical ray up from O
 * meets no ball, so O is joined to the vertex at infinity (a sufficient test; overhangs are refused).
 */
export function inversionCentreProblem(inf: InfiniteSphairahedron, o: Vec3): string | null {
  if (!o.every(Number.isFinite)) return 'the inversion centre is not finite';
  for (let k = 0; k < inf.planes.length; k++)
    if (planeSignedDistance(inf.planes[k], o) <= CENTRE_MARGIN)
      return `the inversion centre is outside the prism (beyond plane F${k + 1}): that face would turn inside out`;
  for (let k = 0; k < inf.spheres.length; k++)
    if (dist3(o, inf.spheres[k].center) - inf.spheres[k].radius <= CENTRE_MARGIN)
      return `the inversion centre is inside sphere S${k + 1}: that face would turn inside out`;
  for (let k = 0; k < inf.spheres.length; k++)
    if (ballTop(inf.spheres[k], o[0], o[1]) > o[2])
      return `the inversion centre is under sphere S${k + 1}: it must be above the spheres, inside the infinite sphairahedron`;
  return null;
}

/** Image of a plane not through the centre of inv: the sphere through c with centre c − n·R²/(2h). */
export function invertPlaneToSphere(inv: Sphere, plane: Plane): Sphere {
  const h = planeSignedDistance(plane, inv.center);
  const rad = (inv.radius * inv.radius) / (2 * Math.abs(h));
  return { center: sub3(inv.center, scale3(plane.normal, Math.sign(h) * rad)), radius: rad };
}

/** The finite sphairahedron: the faces inverted in `inv`, and the seed ball (see FiniteSphairahedron). */
export function finiteSphairahedron(inf: InfiniteSphairahedron, inv: Sphere): Result<FiniteSphairahedron> {
  if (!(inv.radius > 0) || !Number.isFinite(inv.radius))
    return fail('the inversion sphere needs a positive radius');
  const problem = inversionCentreProblem(inf, inv.center);
  if (problem) return fail(problem);
  const spheres: Sphere[] = inf.planes.map((p) => invertPlaneToSphere(inv, p));
  for (const s of inf.spheres) {
    const image = invertSphere(inv, s);
    if (image.kind !== 'sphere') return fail('the inversion centre lies on a sphere face');
    spheres.push(image.sphere);
  }
  const seed = invertPlaneToSphere(inv, { point: [0, 0, inf.floorTop], normal: [0, 0, 1] });
  return ok({ spheres, seed });
}

/** The IIS elements of the infinite sphairahedron: the prism mirrors, then the spheres. */
export const infiniteElements = (inf: InfiniteSphairahedron): Element3d[] => [
  ...inf.planes.map((plane) => ({ kind: 'plane-reflection' as const, plane })),
  ...inf.spheres.map((sphere) => ({ kind: 'sphere-inversion' as const, sphere })),
];

/** The IIS elements of the finite sphairahedron: an inversion in each of its spheres. */
export const finiteElements = (fin: FiniteSphairahedron): Element3d[] =>
  fin.spheres.map((sphere) => ({ kind: 'sphere-inversion' as const, sphere }));

/**
 * The seed of the infinite picture: the part of the prism below the initial hyperplane, as a box
 * that covers the triangle (what lies outside the prism is folded in before it is tested) and
 * reaches `depth` below the floor.
 */
export function infiniteSeedBox(inf: InfiniteSphairahedron, depth = 50): { center: Vec3; halfSize: Vec3 } {
  const reach = (i: 0 | 1) => 1.05 * Math.max(...inf.corners.map((c) => Math.abs(c[i])));
  return { center: [0, 0, inf.floorTop - depth], halfSize: [reach(0), reach(1), depth] };
}

/** A default inversion sphere for a shape: above the triangle's centroid, clear of the spheres. */
export function defaultInversionSphere(inf: InfiniteSphairahedron): Sphere {
  const top = Math.max(...inf.spheres.map((s) => s.center[2] + s.radius));
  const mean = (i: 0 | 1) => inf.corners.reduce((s, c) => s + c[i], 0) / inf.corners.length;
  return { center: [mean(0), mean(1), top + 1], radius: 1.5 };
}

export { CAKE_TYPES, CUBE_TYPES, SPHAIRAHEDRON_TYPES };
