/**
 * The CPU walk of one point (the reference the GLSL walk mirrors): the IIS of docs/math-3d.md §4
 * over the scene's elements, recording one stack entry per inversion, then the safe distance
 * bound folded back through the stack (docs/math-3d.md "§8 The tracer's distance bound"):
 *
 *   D_end = min(seed distances, covers of the orbit inside every region, each raised to its
 *           mirrored cover where larger) at the final point,
 *   D ← max(r_k²·D/(far_k·(far_k + D)), min(local_k, r_k²·D/(far_k·min(reach_k, far_k + D))))
 *   for k = top−1 … 0.
 *
 * cover_j is max(distance to the content ball H_j, distance to the ball B_j) for a sphere inversion
 * (the orbit inside B_j lies in H_j ∩ B_j), else the distance to the element's region itself; an
 * inversion record of sphere-inversion element i has local = min(seeds, cover_j, j ≠ i) and
 * reach = M_i; the inversions inside the other kinds have local = reach = ∞ (the triangle
 * inequality alone: the conservative fallback). The walk also gives the seed-image distance
 * min over seeds of seedDistance(final)/factor, on which the tracer decides a hit.
 */
import type { Walk3dState } from './elements/element-3d-kind.ts';
import { ballDistance } from './elements/sphere-inversion.ts';
import { STACK_CAPACITY, type TracePlan } from './plan.ts';
import { seedDistance } from './seeds-3d.ts';

export interface Walk3dResult {
  /** A lower bound of the distance from the start point to the orbit (∞ when recording is off). */
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

/** One stack of float64 records (local, r², far, reach) per plan user: the CPU tracer is single-threaded. */
const stack = new Float64Array(4 * STACK_CAPACITY);

/** Distance from (x, y, z) to the seeds; sets `nearest.seed` to the nearest one's index. */
function seedsDistance(plan: TracePlan, x: number, y: number, z: number, nearest: { seed: number }): number {
  let d = Number.POSITIVE_INFINITY;
  plan.scene.seeds.forEach((s, k) => {
    const ds = seedDistance(s, x, y, z);
    if (ds < d) {
      d = ds;
      nearest.seed = k;
    }
  });
  return d;
}

/**
 * min(seeds, cover_j for j ≠ skip): a lower bound of the distance to the orbit outside element
 * `skip`. `mirrored`: each cover that would lower the minimum also tries its mirrored cover.
 */
function coverDistance(
  plan: TracePlan,
  x: number,
  y: number,
  z: number,
  skip: number,
  mirrored = false,
): number {
  let d = Math.max(0, seedsDistance(plan, x, y, z, { seed: -1 }));
  plan.scene.elements.forEach((e, j) => {
    if (j === skip) return;
    const h = plan.hulls[j];
    const region = plan.records[j]!.cpu.regionDistance(e, x, y, z);
    let cover = h ? Math.max(region, ballDistance(x, y, z, h.center, h.radius)) : region;
    // Only a cover below the minimum so far can change it: the others need no mirror.
    if (mirrored && cover < d) cover = Math.max(cover, mirroredCover(plan, x, y, z, j));
    d = Math.min(d, cover);
  });
  return d;
}

/** Scratch state for the mirror image p* (the CPU tracer is single-threaded, like the stack). */
const mirrorImage: Walk3dState = { x: 0, y: 0, z: 0, s: 1, depth: 0 };

/**
 * The mirrored cover of element j, a lower bound of dist(p, orbit ∩ region_j) when j is one
 * involution ι (docs/math-3d.md "§8 The tracer's distance bound"): orbit ∩ region_j =
 * ι(orbit \ region_j), so it is L_j at p* = ι(p) (the seeds and the other covers) folded back
 * through ι like a record (unchanged for a reflection). 0 for the other kinds.
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

/**
 * One step of the fold (docs/math-3d.md "§8 The tracer's distance bound"): the better of two safe
 * bounds at the point before the inversion, given D ≤ dist(x', orbit):
 *   split: min(L, r²D/(F·min(M, F + D)))  (orbit outside the ball ≥ L away, inside it via M);
 *   whole: r²D/(F·(F + D))                (the orbit is its own image, no split).
 * The split one is tighter unless L is small: where the balls overlap (dihedral angles π/n, the
 * sphairahedra) a point in this ball may lie in another's cover, L = 0, and the split alone
 * would stall the march there; the whole-orbit one stays positive.
 */
function foldRecord(local: number, r2: number, far: number, reach: number, d: number): number {
  const whole = r2 * (d / (far * (far + d)));
  return Math.max(whole, Math.min(local, r2 * (d / (far * Math.min(reach, far + d)))));
}

/**
 * Walks (x, y, z). `record`: keep the stack and return the safe bound `de`; the walk then also
 * stops when the stack could not take another application (as the budget running out).
 */
export function walk3d(plan: TracePlan, x: number, y: number, z: number, record: boolean): Walk3dResult {
  const { scene, records } = plan;
  const st: Walk3dState = { x, y, z, s: 1, depth: 0 };
  let top = 0;
  let current = 0;
  const push = record
    ? (r2: number, far: number) => {
        const o = 4 * top++;
        stack[o] = plan.hulls[current]
          ? coverDistance(plan, st.x, st.y, st.z, current)
          : Number.POSITIVE_INFINITY;
        stack[o + 1] = r2;
        stack[o + 2] = far;
        stack[o + 3] = plan.reach[current]!;
      }
    : null;
  let escaped = false;
  while (st.depth < scene.maxIterations && (!record || top + plan.maxRecordsPerStep <= STACK_CAPACITY)) {
    let moved = false;
    for (let i = 0; i < records.length; i++) {
      current = i;
      if (records[i]!.cpu.step(scene.elements[i]!, st, push)) {
        moved = true;
        break;
      }
    }
    if (!moved) {
      escaped = true;
      break;
    }
  }
  const nearest = { seed: -1 };
  const image = seedsDistance(plan, st.x, st.y, st.z, nearest) / st.s;
  let de = Number.POSITIVE_INFINITY;
  if (record) {
    de = coverDistance(plan, st.x, st.y, st.z, -1, true);
    for (let k = top - 1; k >= 0; k--) {
      const o = 4 * k;
      const far = stack[o + 2]!;
      de = foldRecord(stack[o]!, stack[o + 1]!, far, stack[o + 3]!, de);
    }
  }
  return {
    de,
    imageDistance: image,
    depth: st.depth,
    seed: nearest.seed,
    x: st.x,
    y: st.y,
    z: st.z,
    factor: st.s,
    escaped,
  };
}
