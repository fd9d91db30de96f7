/**
 * What the sphere tracer needs beyond the Scene3d, computed once per scene (CPU, in float64) and
 * used by both twins — the CPU walk reads it, the GLSL generator uploads it: the element records,
 * the content balls and reaches of the bound, and the scene's bounding ball (docs/math-3d.md "§8 The tracer's distance bound").
 * The bound assumes the seeds lie in the fundamental domain; the render-3d node warns when one does
 * not (KF314, docs/math-3d.md §7).
 */
import type { Element3d, Scene3d } from '../../nodes/core/scene-3d.ts';
import { invertSphere, type Sphere } from '../../nodes/geometry/space/sphere.ts';
import { add3, dist3, len3, scale3, sub3, type Vec3 } from '../../nodes/geometry/space/vec3.ts';
import type { ElementRecord3d } from './elements/element-3d-kind.ts';
import { elementRecord3d } from './elements/index.ts';
import { seedBall } from './seeds-3d.ts';

/** Rounds of the content-ball refinement (each one is a valid cover; more only tightens). */
const HULL_ROUNDS = 6;
/** An unbounded orbit (plane mirrors, outside regions) is traced this many scene radii beyond its centre. */
export const UNBOUNDED_REACH = 24;

export interface TracePlan {
  readonly scene: Scene3d;
  readonly records: readonly ElementRecord3d[];
  /**
   * Per element: a ball holding every orbit point inside a sphere inversion's ball (its content
   * ball, docs/math-3d.md "§8 The tracer's distance bound"); null for the other kinds, whose regions themselves are the cover.
   */
  readonly hulls: readonly (Sphere | null)[];
  /**
   * Per element: M_i ≥ |y − c_i| for every orbit point y outside inversion sphere i (finite when
   * every element is a sphere inversion); ∞ otherwise.
   */
  readonly reach: readonly number[];
  /** Every element a sphere inversion: their (c, r²) packed for the CPU walk's hot loop; else null. */
  readonly inversionRows: Float64Array | null;
  /**
   * Every element a sphere inversion: per element (c, r, content-ball centre, its radius) packed
   * for the CPU walk's covers; else null.
   */
  readonly coverRows: Float64Array | null;
  /** Every element a sphere inversion, closed balls pairwise disjoint, seeds outside them (Fig. 11). */
  readonly disjoint: boolean;
  /**
   * A ball holding the orbit (bounded: the seeds and the content balls, or the regions) or the
   * finite part of the scene (unbounded).
   */
  readonly bounds: Sphere;
  readonly bounded: boolean;
}

const gap = (a: Sphere, b: Sphere): number => dist3(a.center, b.center) - a.radius - b.radius;

/** Rounds of the Bădoiu–Clarkson walk towards the smallest enclosing ball. */
const ENCLOSING_ROUNDS = 200;

/**
 * A ball holding `balls`, near the smallest: start at the centre of their bounding box, step
 * towards the farthest point by 1/(k + 2) of the way (Bădoiu–Clarkson), keep the best centre;
 * the radius is whatever reaches every ball from it (always a valid enclosing ball).
 */
export function enclosingBall(balls: readonly Sphere[]): Sphere {
  const reachFrom = (c: Vec3) => Math.max(...balls.map((b) => dist3(c, b.center) + b.radius));
  const lo = [0, 1, 2].map((k) => Math.min(...balls.map((b) => b.center[k]! - b.radius)));
  const hi = [0, 1, 2].map((k) => Math.max(...balls.map((b) => b.center[k]! + b.radius)));
  let c: Vec3 = [(lo[0]! + hi[0]!) / 2, (lo[1]! + hi[1]!) / 2, (lo[2]! + hi[2]!) / 2];
  let best = { center: c, radius: reachFrom(c) };
  for (let k = 0; k < ENCLOSING_ROUNDS; k++) {
    let far = balls[0]!;
    let farD = -1;
    for (const b of balls) {
      const d = dist3(c, b.center) + b.radius;
      if (d > farD) [far, farD] = [b, d];
    }
    const toC = dist3(c, far.center);
    const u = toC > 0 ? scale3(sub3(far.center, c), 1 / toC) : ([0, 0, 0] as Vec3);
    const p = add3(far.center, scale3(u, far.radius));
    c = add3(c, scale3(sub3(p, c), 1 / (k + 2)));
    const r = reachFrom(c);
    if (r < best.radius) best = { center: c, radius: r };
  }
  return best;
}

/** The image of ball b in inversion sphere m when m's centre lies outside b's closure, else null. */
function imageBall(m: Sphere, b: Sphere): Sphere | null {
  if (dist3(b.center, m.center) <= b.radius) return null;
  const img = invertSphere(m, b);
  return img.kind === 'sphere' ? img.sphere : null;
}

/** The inversion spheres when every element is one, else null. */
const allInversions = (elements: readonly Element3d[]): Sphere[] | null =>
  elements.every((e) => e.kind === 'sphere-inversion')
    ? elements.map((e) => (e as Extract<Element3d, { kind: 'sphere-inversion' }>).sphere)
    : null;

function isDisjoint(mirrors: readonly Sphere[], seeds: readonly Sphere[]): boolean {
  return mirrors.every(
    (m, i) => mirrors.every((o, j) => j <= i || gap(m, o) > 0) && seeds.every((s) => gap(m, s) > 0),
  );
}

/**
 * Content balls H_i with orbit ∩ B_i ⊂ H_i ∩ B_i (docs/math-3d.md "§8 The tracer's distance bound"):
 * start from H_i = B_i and repeat H_i ← enclosingBall(pieces), the pieces being I_i(seed ball) and,
 * for j ≠ i, the smaller of I_i(H_j) and I_i(B_j) (both hold I_i(orbit ∩ B_j)); a round needs every
 * piece to be a ball (c_i outside the inverted ball) and keeps the new ball only when it is smaller.
 * Each round is a valid cover by induction: orbit ∩ B_i = I_i(orbit \ B_i) and
 * orbit \ B_i ⊂ seeds ∪ ⋃_{j≠i} (H_j ∩ B_j). Also returns, per mirror, the last round's pieces (they
 * cover orbit ∩ B_i too, more tightly than their enclosing ball), or [H_i] where no round applied.
 */
function contentBalls(mirrors: readonly Sphere[], seeds: readonly Sphere[]) {
  let hulls = [...mirrors];
  let cover: Sphere[][] = mirrors.map((m) => [m]);
  for (let round = 0; round < HULL_ROUNDS; round++) {
    const next = mirrors.map((m, i): { hull: Sphere; pieces: Sphere[] } => {
      const keep = { hull: hulls[i]!, pieces: cover[i]! };
      const pieces: Sphere[] = [];
      for (const s of seeds) {
        const img = imageBall(m, s);
        if (!img) return keep;
        pieces.push(img);
      }
      for (let j = 0; j < mirrors.length; j++) {
        if (j === i) continue;
        const viaHull = imageBall(m, hulls[j]!);
        const viaBall = imageBall(m, mirrors[j]!);
        const img =
          viaHull && viaBall ? (viaHull.radius < viaBall.radius ? viaHull : viaBall) : (viaHull ?? viaBall);
        if (!img) return keep;
        pieces.push(img);
      }
      if (pieces.length === 0) return keep;
      const h = enclosingBall(pieces);
      return h.radius < hulls[i]!.radius ? { hull: h, pieces } : keep;
    });
    hulls = next.map((n) => n.hull);
    cover = next.map((n) => n.pieces);
  }
  return { hulls, cover };
}

/**
 * M_i ≥ |y − c_i| over the orbit outside B_i ⊂ seeds ∪ ⋃_{j≠i} (H_j ∩ B_j): the largest over seed
 * balls of |c − c_i| + r, and over j of the smaller of that for H_j and for B_j.
 */
function reachOf(
  mirrors: readonly Sphere[],
  hulls: readonly Sphere[],
  seeds: readonly Sphere[],
  i: number,
): number {
  const c = mirrors[i]!.center;
  const far = (b: Sphere) => dist3(b.center, c) + b.radius;
  const others = mirrors.flatMap((m, j) => (j === i ? [] : [Math.min(far(m), far(hulls[j]!))]));
  return Math.max(0, ...seeds.map(far), ...others);
}

/** Whether every region of the element is a bounded ball (the orbit inside it is bounded). */
export function boundedRegions(e: Element3d): Sphere[] | null {
  switch (e.kind) {
    case 'sphere-inversion':
      return [e.sphere];
    case 'mobius-3d':
      return e.g.a.inside && e.g.b.inside ? [e.g.a.sphere, e.g.b.sphere] : null;
    case 'compound-loxodromic-3d':
      return e.g.base.a.inside && e.g.base.b.inside ? [e.g.base.a.sphere, e.g.base.b.sphere] : null;
    default:
      return null;
  }
}

/** A finite stand-in for an unbounded element: a point of it, radius 0. */
function anchor(e: Element3d): Sphere {
  switch (e.kind) {
    case 'plane-reflection':
      return { center: e.plane.point, radius: 0 };
    case 'compound-parabolic-3d':
      return { center: e.g.point, radius: e.g.gap };
    case 'mobius-3d':
      return e.g.s1;
    case 'compound-loxodromic-3d':
      return e.g.base.s1;
    case 'sphere-inversion':
      return e.sphere;
    case 'box-fold':
      return { center: e.box.center, radius: len3(e.box.halfSize) };
  }
}

export function prepareTrace3d(scene: Scene3d): TracePlan {
  const records = scene.elements.map((e) => elementRecord3d(e) as ElementRecord3d);
  const seedBalls = scene.seeds.map(seedBall);
  const mirrors = allInversions(scene.elements);
  const content = mirrors ? contentBalls(mirrors, seedBalls) : null;
  const hulls = content ? content.hulls : scene.elements.map(() => null);
  const reach = scene.elements.map((_, i) =>
    mirrors ? reachOf(mirrors, hulls as Sphere[], seedBalls, i) : Number.POSITIVE_INFINITY,
  );
  const regions = scene.elements.map(boundedRegions);
  const bounded = regions.every((r) => r !== null);
  // The orbit lies in the seeds and the content balls' pieces (tighter than the mirror balls);
  // without content balls, in the seeds and the regions.
  const finite = [
    ...seedBalls,
    ...(content ? content.cover.flat() : regions.flatMap((r, i) => r ?? [anchor(scene.elements[i]!)])),
  ];
  const bounds = finite.length > 0 ? enclosingBall(finite) : { center: scene.camera.target, radius: 1 };
  return {
    scene,
    records,
    hulls,
    reach,
    inversionRows: mirrors
      ? Float64Array.from(mirrors.flatMap((m) => [...m.center, m.radius * m.radius]))
      : null,
    coverRows: mirrors
      ? Float64Array.from(
          mirrors.flatMap((m, i) => [...m.center, m.radius, ...hulls[i]!.center, hulls[i]!.radius]),
        )
      : null,
    disjoint: mirrors !== null && isDisjoint(mirrors, seedBalls),
    bounds: { center: bounds.center, radius: Math.max(bounds.radius, 1e-6) },
    bounded,
  };
}
