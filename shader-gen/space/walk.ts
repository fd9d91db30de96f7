/**
 * The CPU walk of one point (the reference the GLSL walk mirrors): the IIS of docs/math-3d.md §4
 * over the scene's elements, and the safe distance bound of docs/math-3d.md "§8 The tracer's
 * distance bound", formed once at the final point and carried back through the composed map W:
 *
 *   D   = min(seed distances, covers of the orbit inside every region, each raised to its
 *         mirrored cover where larger) at the final point x_f = W(x),
 *   R   ≤ |x_f − W(∞)|, the distance from the final point to the pole of W⁻¹,
 *   DE  = R·D / (s·(R + D)) = D / (s·(1 + D/R)),  s the accumulated conformal factor.
 *
 * The walk moves the pole W(∞) with the point (from a stand-in for ∞ far away), so one IIS step costs
 * one plain application plus the same map on the pole, and the O(n) covers are evaluated once, at
 * the end (with mirrored covers only for the covers below the running minimum). The walk also gives the seed-image
 * distance min over seeds of seedDistance(final)/factor, on which the tracer decides a hit.
 */
import { POLE_AT_INFINITY, type Pole3d, type Walk3dState } from './elements/element-3d-kind.ts';
import { invertPoint } from './elements/invert.ts';
import { ballDistance } from './elements/sphere-inversion.ts';
import type { TracePlan } from './plan.ts';
import { seedDistance } from './seeds-3d.ts';

export interface Walk3dResult {
  /** A lower bound of the distance from the start point to the orbit (∞ when not asked for). */
  de: number;
  /** min over seeds of seedDistance(final point)/factor: ≈ the distance to the nearest seed image. */
  imageDistance: number;
  /** Element applications. */
  depth: number;
  /** Index of the seed nearest to the final point (−1: no seeds). */
  seed: number;
  x: number;
  y: number;
  z: number;
  factor: number;
  /** The point left every region (reached the fundamental domain) within the budget. */
  escaped: boolean;
}

/** Distance from (x, y, z) to the seeds; sets `nearest.seed` to the nearest one's index. */
function seedsDistance(plan: TracePlan, x: number, y: number, z: number, nearest: { seed: number }): number {
  const seeds = plan.scene.seeds;
  let d = Number.POSITIVE_INFINITY;
  for (let k = 0; k < seeds.length; k++) {
    const ds = seedDistance(seeds[k]!, x, y, z);
    if (ds < d) {
      d = ds;
      nearest.seed = k;
    }
  }
  return d;
}

/** Scratch for the seed index where it is not wanted (the CPU tracer is single-threaded). */
const unused = { seed: -1 };
/** Scratch for the final point's nearest seed (one walk at a time: no allocation per march step). */
const nearest = { seed: -1 };

/** cover_j at (x, y, z): the content ball and the region where both are known, else the region. */
function coverOf(plan: TracePlan, x: number, y: number, z: number, j: number): number {
  const rows = plan.coverRows;
  if (rows) {
    // max(d(x, B_j), d(x, H_j)) from the packed (c, r, hull centre, hull radius) row.
    const o = 8 * j;
    const b =
      Math.sqrt((x - rows[o]!) ** 2 + (y - rows[o + 1]!) ** 2 + (z - rows[o + 2]!) ** 2) - rows[o + 3]!;
    const h =
      Math.sqrt((x - rows[o + 4]!) ** 2 + (y - rows[o + 5]!) ** 2 + (z - rows[o + 6]!) ** 2) - rows[o + 7]!;
    return Math.max(0, b, h);
  }
  const h = plan.hulls[j];
  const region = plan.records[j]!.cpu.regionDistance(plan.scene.elements[j]!, x, y, z);
  return h ? Math.max(region, ballDistance(x, y, z, h.center, h.radius)) : region;
}

/** min(seeds, cover_j for j ≠ skip): a lower bound of the distance to the orbit outside element `skip`. */
function coverDistance(plan: TracePlan, x: number, y: number, z: number, skip: number): number {
  let d = Math.max(0, seedsDistance(plan, x, y, z, unused));
  for (let j = 0; j < plan.records.length; j++) if (j !== skip) d = Math.min(d, coverOf(plan, x, y, z, j));
  return d;
}

/**
 * D at the final point: min(seeds, covers), the nearest cover raised to its mirrored cover (where
 * that is larger) — the others are not the minimum, so one mirror, O(n) in all, is what can help.
 */
function endDistance(plan: TracePlan, x: number, y: number, z: number): number {
  let best = Math.max(0, seedsDistance(plan, x, y, z, unused));
  let second = Number.POSITIVE_INFINITY;
  let nearest = -1;
  for (let j = 0; j < plan.records.length; j++) {
    const c = coverOf(plan, x, y, z, j);
    if (c < best) {
      second = best;
      best = c;
      nearest = j;
    } else second = Math.min(second, c);
  }
  if (nearest < 0) return best;
  return Math.min(second, Math.max(best, mirroredCover(plan, x, y, z, nearest)));
}

/** Scratch state for the mirror image p* (the CPU tracer is single-threaded). */
const mirrorImage: Walk3dState = { x: 0, y: 0, z: 0, s: 1, depth: 0, pole: null };

/**
 * The mirrored cover of element j, a lower bound of dist(p, orbit ∩ region_j) when j is one
 * involution ι (docs/math-3d.md "§8 The tracer's distance bound"): orbit ∩ region_j =
 * ι(orbit \ region_j), so it is L_j at p* = ι(p) (the seeds and the other covers) carried back
 * through ι: r²·L/(F·min(M_j, F + L)), F = |p* − c| (unchanged for a reflection). 0 for the other kinds.
 */
function mirroredCover(plan: TracePlan, x: number, y: number, z: number, j: number): number {
  const cpu = plan.records[j]!.cpu;
  if (!cpu.mirror) return 0;
  const r2 = cpu.mirror(plan.scene.elements[j]!, x, y, z, mirrorImage);
  const local = coverDistance(plan, mirrorImage.x, mirrorImage.y, mirrorImage.z, j);
  if (r2 === 0) return local;
  const far = Math.sqrt(mirrorImage.s * r2); // |p* − c| = r²/|p − c|, the factor s being r²/|p − c|²
  return r2 * (local / (far * Math.min(plan.reach[j]!, far + local)));
}

/** |x_f − W(∞)| (about 10¹⁸ while W is an isometry: the bound is then D/s to float precision). */
const poleDistance = (st: Walk3dState, pole: Pole3d): number =>
  Math.sqrt((st.x - pole.x) ** 2 + (st.y - pole.y) ** 2 + (st.z - pole.z) ** 2);

/** The bound carried back through W: R·D/(s·(R + D)), written to stay finite for R = ∞. */
export const composedBound = (d: number, s: number, r: number): number => d / (s * (1 + d / r));

/**
 * The IIS over sphere inversions only, from packed (c, r²) rows: the same steps as the elements'
 * own (sphereInversion.step and invertWalk), without a call and a destructuring per element tested
 * — the CPU tracer's hot loop for Figs. 11–12 and the sphairahedra. Returns `escaped`.
 */
function walkInversions(rows: Float64Array, maxIterations: number, st: Walk3dState): boolean {
  const pole = st.pole;
  const n = rows.length;
  outer: while (st.depth < maxIterations) {
    for (let o = 0; o < n; o += 4) {
      const cx = rows[o]!;
      const cy = rows[o + 1]!;
      const cz = rows[o + 2]!;
      const r2 = rows[o + 3]!;
      const dx = st.x - cx;
      const dy = st.y - cy;
      const dz = st.z - cz;
      const d2 = dx * dx + dy * dy + dz * dz;
      if (!(d2 < r2)) continue;
      st.s *= invertPoint(st, cx, cy, cz, r2);
      if (pole) invertPoint(pole, cx, cy, cz, r2);
      st.depth += 1;
      continue outer;
    }
    return true;
  }
  return false;
}

/** The IIS over the scene's elements, each by its kind's step. Returns `escaped`. */
function walkElements(plan: TracePlan, st: Walk3dState): boolean {
  const { scene, records } = plan;
  while (st.depth < scene.maxIterations) {
    let moved = false;
    for (let i = 0; i < records.length; i++) {
      if (records[i]!.cpu.step(scene.elements[i]!, st)) {
        moved = true;
        break;
      }
    }
    if (!moved) return true;
  }
  return false;
}

/** Scratch walk state and pole, reset by every walk (the CPU tracer is single-threaded). */
const scratchPole: Pole3d = { x: 0, y: 0, z: 0 };
const scratch: Walk3dState = { x: 0, y: 0, z: 0, s: 1, depth: 0, pole: null };

/** A fresh result to fill (the default `out` of walk3d). */
export const walkResult = (): Walk3dResult => ({
  de: 0,
  imageDistance: 0,
  depth: 0,
  seed: -1,
  x: 0,
  y: 0,
  z: 0,
  factor: 1,
  escaped: false,
});

/**
 * Walks (x, y, z). `bound`: also form the safe distance bound `de` (else it is ∞). The result is
 * written to `out` (hot loops pass one they reuse, so a march allocates nothing) and returned.
 */
export function walk3d(
  plan: TracePlan,
  x: number,
  y: number,
  z: number,
  bound: boolean,
  out: Walk3dResult = walkResult(),
): Walk3dResult {
  const st = scratch;
  st.x = x;
  st.y = y;
  st.z = z;
  st.s = 1;
  st.depth = 0;
  const pole = bound ? scratchPole : null;
  if (pole) {
    pole.x = POLE_AT_INFINITY;
    pole.y = 0;
    pole.z = 0;
  }
  st.pole = pole;
  const escaped = plan.inversionRows
    ? walkInversions(plan.inversionRows, plan.scene.maxIterations, st)
    : walkElements(plan, st);
  nearest.seed = -1;
  out.imageDistance = seedsDistance(plan, st.x, st.y, st.z, nearest) / st.s;
  out.de = pole
    ? composedBound(endDistance(plan, st.x, st.y, st.z), st.s, poleDistance(st, pole))
    : Number.POSITIVE_INFINITY;
  out.depth = st.depth;
  out.seed = nearest.seed;
  out.x = st.x;
  out.y = st.y;
  out.z = st.z;
  out.factor = st.s;
  out.escaped = escaped;
  return out;
}
