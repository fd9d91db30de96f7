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
import { budgetBound } from './budget-bound.ts';
import { POLE_AT_INFINITY, type Pole3d, type Walk3dState } from './elements/element-3d-kind.ts';
import { invertPoint, TINY_D2 } from './elements/invert.ts';
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

/**
 * cover_j from packed (c, r, hull centre, hull radius) rows: max(0, d(x, B_j), d(x, H_j)) — or,
 * when that is at least `cap`, possibly just `cap` (callers only take minima below cap): the ball
 * test on squared distances then skips both square roots, as it does for most far elements.
 */
function packedCover(rows: Float64Array, x: number, y: number, z: number, j: number, cap: number): number {
  const o = 8 * j;
  const b2 = (x - rows[o]!) ** 2 + (y - rows[o + 1]!) ** 2 + (z - rows[o + 2]!) ** 2;
  const bCap = cap + rows[o + 3]!;
  if (b2 >= bCap * bCap) return cap; // d(x, B_j) ≥ cap (cap ≥ 0, so bCap > 0)
  const h2 = (x - rows[o + 4]!) ** 2 + (y - rows[o + 5]!) ** 2 + (z - rows[o + 6]!) ** 2;
  const hCap = cap + rows[o + 7]!;
  if (h2 >= hCap * hCap) return cap;
  return Math.max(0, Math.sqrt(b2) - rows[o + 3]!, Math.sqrt(h2) - rows[o + 7]!);
}

/**
 * cover_j at (x, y, z): the content ball and the region where both are known, else the region —
 * at the final point (`atEnd`) the element's own end cover where it has one (the box fold's).
 */
function coverOf(plan: TracePlan, x: number, y: number, z: number, j: number, atEnd = false): number {
  if (plan.coverRows) return packedCover(plan.coverRows, x, y, z, j, Number.POSITIVE_INFINITY);
  const h = plan.hulls[j];
  const cpu = plan.records[j]!.cpu;
  const e = plan.scene.elements[j]!;
  const region = atEnd && cpu.endCover ? cpu.endCover(e, x, y, z) : cpu.regionDistance(e, x, y, z);
  return h ? Math.max(region, ballDistance(x, y, z, h.center, h.radius)) : region;
}

/**
 * D at the final point: min(seeds, covers), the nearest cover raised to its mirrored cover (where
 * that is larger) — the others are not the minimum, so one mirror, O(n) in all, is what can help.
 * `seeds` is min over seeds of seedDistance there (the walk has it already).
 */
function endDistance(plan: TracePlan, x: number, y: number, z: number, seeds: number): number {
  let best = Math.max(0, seeds);
  let second = Number.POSITIVE_INFINITY;
  let nearest = -1;
  for (let j = 0; j < plan.records.length; j++) {
    const c = coverOf(plan, x, y, z, j, true);
    if (c < best) {
      second = best;
      best = c;
      nearest = j;
    } else second = Math.min(second, c);
  }
  if (nearest < 0) return best;
  return Math.min(second, Math.max(best, mirroredCover(plan, x, y, z, nearest, best)));
}

/** L at p* carried back through the mirror: r²·L/(F·min(M, F + L)); L itself for a reflection (r² = 0). */
const carryBack = (l: number, r2: number, far: number, reach: number): number =>
  r2 === 0 ? l : r2 * (l / (far * Math.min(reach, far + l)));

/** Scratch state for the mirror image p* (the CPU tracer is single-threaded). */
const mirrorImage: Walk3dState = { x: 0, y: 0, z: 0, s: 1, depth: 0, pole: null };

/**
 * The mirrored cover of element j, a lower bound of dist(p, orbit ∩ region_j) when j is one
 * involution ι (docs/math-3d.md "§8 The tracer's distance bound"): orbit ∩ region_j =
 * ι(orbit \ region_j), so it is L_j at p* = ι(p) (the seeds and the other covers) carried back
 * through ι: r²·L/(F·min(M_j, F + L)), F = |p* − c| (unchanged for a reflection). 0 for the other kinds.
 * That value grows with L and L only falls as covers are taken in, so once it is ≤ `floor` (the
 * caller keeps the larger of the two) the rest of the covers cannot matter: it returns `floor` then.
 */
function mirroredCover(plan: TracePlan, x: number, y: number, z: number, j: number, floor: number): number {
  const cpu = plan.records[j]!.cpu;
  if (!cpu.mirror) return 0;
  const r2 = cpu.mirror(plan.scene.elements[j]!, x, y, z, mirrorImage);
  const far = Math.sqrt(mirrorImage.s * r2); // |p* − c| = r²/|p − c|, the factor s being r²/|p − c|²
  const reach = plan.reach[j]!;
  const { x: qx, y: qy, z: qz } = mirrorImage;
  let local = Math.max(0, seedsDistance(plan, qx, qy, qz, unused));
  if (carryBack(local, r2, far, reach) <= floor) return floor;
  for (let k = 0; k < plan.records.length; k++) {
    if (k === j) continue;
    local = Math.min(local, coverOf(plan, qx, qy, qz, k));
    if (carryBack(local, r2, far, reach) <= floor) return floor;
  }
  return carryBack(local, r2, far, reach);
}

/**
 * endDistance for scenes of sphere inversions only (packed `inversionRows` and `coverRows`): the
 * same minimum, nearest cover and mirrored cover, with the mirror inversion written out and no
 * per-element record lookups — the other half of the CPU tracer's hot path.
 */
function packedEndDistance(
  plan: TracePlan,
  inv: Float64Array,
  covers: Float64Array,
  x: number,
  y: number,
  z: number,
  seeds: number,
): number {
  const n = inv.length >> 2;
  let best = Math.max(0, seeds);
  let second = Number.POSITIVE_INFINITY;
  let nearest = -1;
  for (let j = 0; j < n; j++) {
    const c = packedCover(covers, x, y, z, j, second);
    if (c < best) {
      second = best;
      best = c;
      nearest = j;
    } else if (c < second) second = c;
  }
  if (nearest < 0) return best;
  // p* = the inversion of p in sphere `nearest` (k = r²/|p − c|²); F = |p* − c| = √(k·r²).
  const o = 4 * nearest;
  const r2 = inv[o + 3]!;
  mirrorImage.x = x;
  mirrorImage.y = y;
  mirrorImage.z = z;
  const k = invertPoint(mirrorImage, inv[o]!, inv[o + 1]!, inv[o + 2]!, r2);
  const { x: qx, y: qy, z: qz } = mirrorImage;
  const far = Math.sqrt(k * r2);
  const reach = plan.reach[nearest]!;
  let local = Math.max(0, seedsDistance(plan, qx, qy, qz, unused));
  let mirrored = carryBack(local, r2, far, reach);
  for (let j = 0; j < n && mirrored > best; j++) {
    if (j === nearest) continue;
    local = Math.min(local, packedCover(covers, qx, qy, qz, j, local));
    mirrored = carryBack(local, r2, far, reach);
  }
  return Math.min(second, Math.max(best, mirrored));
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
  // The state lives in locals for the loop (V8 keeps them in registers; fields are reloaded and
  // stored at every step) and goes back to `st` at the end.
  const pole = st.pole;
  const n = rows.length;
  let { x, y, z, s, depth } = st;
  let px = pole ? pole.x : 0;
  let py = pole ? pole.y : 0;
  let pz = pole ? pole.z : 0;
  let escaped = false;
  outer: while (depth < maxIterations) {
    for (let o = 0; o < n; o += 4) {
      const cx = rows[o]!;
      const cy = rows[o + 1]!;
      const cz = rows[o + 2]!;
      const r2 = rows[o + 3]!;
      const dx = x - cx;
      const dy = y - cy;
      const dz = z - cz;
      const d2 = dx * dx + dy * dy + dz * dz;
      if (!(d2 < r2)) continue;
      // invertPoint's formula, inline: k = r²/max(|d|², TINY), x ← c + k·d, s ← s·k.
      const k = r2 / Math.max(d2, TINY_D2);
      x = cx + dx * k;
      y = cy + dy * k;
      z = cz + dz * k;
      s *= k;
      const ex = px - cx;
      const ey = py - cy;
      const ez = pz - cz;
      const kp = r2 / Math.max(ex * ex + ey * ey + ez * ez, TINY_D2);
      px = cx + ex * kp;
      py = cy + ey * kp;
      pz = cz + ez * kp;
      depth += 1;
      continue outer;
    }
    escaped = true;
    break;
  }
  st.x = x;
  st.y = y;
  st.z = z;
  st.s = s;
  st.depth = depth;
  if (pole) {
    pole.x = px;
    pole.y = py;
    pole.z = pz;
  }
  return escaped;
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

/** The shared walk state, set to the start of a walk from (x, y, z): scale 1, depth 0. */
function startWalk(x: number, y: number, z: number): Walk3dState {
  const st = scratch;
  st.x = x;
  st.y = y;
  st.z = z;
  st.s = 1;
  st.depth = 0;
  return st;
}

/**
 * The depth alone of (x, y, z): the same IIS steps as walk3d (the same element order and budget),
 * without the pole, the seeds or the bound — what the volume renderer samples (volume-3d.ts).
 */
export function walkDepth3d(plan: TracePlan, x: number, y: number, z: number): number {
  const st = startWalk(x, y, z);
  st.pole = null;
  if (plan.inversionRows) walkInversions(plan.inversionRows, plan.scene.maxIterations, st);
  else walkElements(plan, st);
  return st.depth;
}

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
 * Walks (x, y, z). `bound`: also form the safe distance bound `de` (else it is ∞; also when the
 * seed-image distance is below `hitBelow`, a hit for the tracer). The result is written to `out`
 * (hot loops pass one they reuse, so a march allocates nothing) and returned.
 */
export function walk3d(
  plan: TracePlan,
  x: number,
  y: number,
  z: number,
  bound: boolean,
  out: Walk3dResult = walkResult(),
  hitBelow = Number.NEGATIVE_INFINITY,
): Walk3dResult {
  const st = startWalk(x, y, z);
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
  const seeds = seedsDistance(plan, st.x, st.y, st.z, nearest);
  out.imageDistance = seeds / st.s;
  // A hit needs no bound: the tracer stops there.
  out.de =
    pole && !(out.imageDistance < hitBelow)
      ? composedBound(
          plan.inversionRows && plan.coverRows
            ? packedEndDistance(plan, plan.inversionRows, plan.coverRows, st.x, st.y, st.z, seeds)
            : endDistance(plan, st.x, st.y, st.z, seeds),
          st.s,
          poleDistance(st, pole),
        )
      : Number.POSITIVE_INFINITY;
  // Out of budget: the drawn set is only what N steps reach, often far nearer than the orbit's bound.
  if (!escaped && out.de < Number.POSITIVE_INFINITY) out.de = budgetBound(plan, x, y, z, seeds, out.de);
  out.depth = st.depth;
  out.seed = nearest.seed;
  out.x = st.x;
  out.y = st.y;
  out.z = st.z;
  out.factor = st.s;
  out.escaped = escaped;
  return out;
}
