/**
 * The infinite cake (docs/math-3d.md "Sphairahedra (paper §5.3)", "The cake"): a rectangular
 * prism of four vertical planes closed below by two spheres, one shape parameter zb.
 */
import { type InfiniteSphairahedron, strayEdge } from './sphairahedron-shared.ts';
import { withOutside } from './sphairahedron-space.ts';
import type { CakeAngles } from './sphairahedron-types.ts';
import type { Plane, Result, Sphere } from './sphere.ts';
import type { Vec3 } from './vec3.ts';

/** The distance between the rectangle's two ends (the published renderer's scale, so zb means the same). */
export const CAKE_LENGTH = Math.SQRT2;

const cosPi = (n: number) => Math.cos(Math.PI / n);

/**
 * The rectangle x ∈ [−L/2, L/2], y ∈ [−w/2, w/2] (ends F1 at −L/2 and F3 at +L/2, long sides F2 at
 * −w/2 and F4 at +w/2, normals inwards) and the two spheres. A sphere meeting a plane at interior
 * angle θ has its centre at r cos θ inside it, so S_i, meeting both long sides, has
 *   w = r_i (cos θ_i2 + cos θ_i4) =: r_i A_i,
 * centre x = ∓(L/2 − r_i cos θ_i,end), y = −w/2 + r_i cos θ_i2, heights 0 and zb. Their angle γ:
 *   (L − w p)² + (w q)² + zb² = w² (1/A₁² + 1/A₂² + 2 cos γ/(A₁A₂)),
 * p = cos θ_1,end/A₁ + cos θ_2,end/A₂, q = cos θ_22/A₂ − cos θ_12/A₁. The w² terms cancel (the
 * two vertices where S1, S2 meet a long side are ideal), leaving w = (L² + zb²)/(2Lp).
 */
export function infiniteCake(type: CakeAngles, zb: number): Result<InfiniteSphairahedron> {
  const L = CAKE_LENGTH;
  const [e1, a1, b1] = type.first.map(cosPi);
  const [e2, a2, b2] = type.second.map(cosPi);
  const A1 = a1 + b1;
  const A2 = a2 + b2;
  const p = e1 / A1 + e2 / A2;
  const w = (L * L + zb * zb) / (2 * L * p);
  const r1 = w / A1;
  const r2 = w / A2;
  const spheres: [Sphere, Sphere] = [
    { center: [-L / 2 + r1 * e1, -w / 2 + r1 * a1, 0], radius: r1 },
    { center: [L / 2 - r2 * e2, -w / 2 + r2 * a2, zb], radius: r2 },
  ];
  const plane = (point: Vec3, normal: Vec3): Plane => ({ point, normal });
  const planes = [
    plane([-L / 2, 0, 0], [1, 0, 0]),
    plane([0, -w / 2, 0], [0, 1, 0]),
    plane([L / 2, 0, 0], [-1, 0, 0]),
    plane([0, w / 2, 0], [0, -1, 0]),
  ];
  // A sphere meeting its far end makes a bridge unless another ball hides the circle.
  const bridges = [strayEdge(planes, spheres, 0, 2), strayEdge(planes, spheres, 1, 0)];
  const corners: Vec3[] = [
    [-L / 2, -w / 2, 0],
    [L / 2, -w / 2, 0],
    [L / 2, w / 2, 0],
    [-L / 2, w / 2, 0],
  ];
  return withOutside({ type, corners, planes, spheres }, bridges);
}
