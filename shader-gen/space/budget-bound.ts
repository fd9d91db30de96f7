/**
 * The distance bound of a walk that ran out of budget (docs/math-3d.md "The bound when the budget
 * runs out"). With max iterations N the tracer draws T_N, the points whose walk reaches a seed
 * within N steps — far fewer than the whole orbit near the limit set, where §8's bound (a bound of
 * the distance to the whole orbit) is tiny. For y ∈ T_N the walks of x and y apply the same maps up
 * to the first step m where they choose differently, and there x_m and y_m lie on different sides
 * of a region's boundary; hence, with W_m the map of the first m steps (factor s_m, pole P_m),
 *
 *   δ_m = min over the elements i tested at x_m up to the one applied (j_m) of dist(x_m, ∂region_i)
 *   δ_N = max(seed distance at x_N, dist(x_N, ∂region_j_N))     (y_N in a seed, outside every region)
 *   dist(x, T_N) ≥ min over m ≤ N of R_m·δ_m / (s_m·(R_m + δ_m)),  R_m = |x_m − P_m|   (§8's lemma).
 *
 * It re-walks the point (only walks that ran out of budget need it) and needs every element's
 * `boundaryDistance`.
 */
import { POLE_AT_INFINITY, type Pole3d, type Walk3dState } from './elements/element-3d-kind.ts';
import { invertWalk } from './elements/invert.ts';
import type { TracePlan } from './plan.ts';

const pole: Pole3d = { x: 0, y: 0, z: 0 };
const st: Walk3dState = { x: 0, y: 0, z: 0, s: 1, depth: 0, pole };

/** R_m = |x_m − P_m| at the walk's current state (read before the step moves both). */
const poleDistance = (): number =>
  Math.sqrt((st.x - pole.x) ** 2 + (st.y - pole.y) ** 2 + (st.z - pole.z) ** 2);

/** R·δ/(s·(R + δ)): §8's composed bound for W_m (factor s_m, R_m = |x_m − P_m|). */
const carried = (delta: number, s: number, r: number): number => delta / (s * (1 + delta / r));

/**
 * The bound above for the walk from (x, y, z) that did not escape within N = maxIterations steps;
 * `seed` is min over seeds of seedDistance at its final point x_N (the walk has it). 0 when some
 * kind has no boundary distance (or the walk escaped after all); `floor` (the caller keeps the larger of it and this) when the
 * bound falls to it, without walking on.
 */
export function budgetBound(
  plan: TracePlan,
  x: number,
  y: number,
  z: number,
  seed: number,
  floor = 0,
): number {
  st.x = x;
  st.y = y;
  st.z = z;
  st.s = 1;
  st.depth = 0;
  pole.x = POLE_AT_INFINITY;
  pole.y = 0;
  pole.z = 0;
  return plan.inversionRows
    ? packedBudget(plan.inversionRows, plan.scene.maxIterations, seed, floor)
    : elementBudget(plan, seed, floor);
}

/** budgetBound over the scene's elements, each by its kind's step and boundary distance. */
function elementBudget(plan: TracePlan, seed: number, floor: number): number {
  const { scene, records } = plan;
  const elements = scene.elements;
  const last = scene.maxIterations;
  let bound = Number.POSITIVE_INFINITY;
  for (let m = 0; m <= last; m++) {
    const { x, y, z, s } = st;
    const r = poleDistance();
    let delta = Number.POSITIVE_INFINITY;
    let applied = -1;
    for (let i = 0; i < records.length && applied < 0; i++) {
      const cpu = records[i]!.cpu;
      if (!cpu.boundaryDistance) return floor;
      const b = cpu.boundaryDistance(elements[i]!, x, y, z);
      delta = m === last ? b : Math.min(delta, b);
      if (cpu.step(elements[i]!, st)) applied = i;
    }
    // At x_N only j_N's boundary counts (a seed point y_N lies outside every region), or none.
    if (m === last) delta = Math.max(applied < 0 ? 0 : delta, seed, 0);
    // Before N every step applied an element, as in the walk (it did not escape).
    else if (applied < 0) return floor;
    bound = Math.min(bound, carried(delta, s, r));
    // The minimum only falls: once it is at the caller's other bound, the rest cannot matter.
    if (bound <= floor) return floor;
  }
  return bound;
}

/** elementBudget for sphere inversions only, from the packed (c, r²) rows (the walk's hot path). */
function packedBudget(rows: Float64Array, last: number, seed: number, floor: number): number {
  let bound = Number.POSITIVE_INFINITY;
  for (let m = 0; m <= last; m++) {
    const { x, y, z, s } = st;
    const r = poleDistance();
    let delta = Number.POSITIVE_INFINITY;
    let applied = -1;
    for (let o = 0; o < rows.length; o += 4) {
      const d2 = (x - rows[o]!) ** 2 + (y - rows[o + 1]!) ** 2 + (z - rows[o + 2]!) ** 2;
      const r2 = rows[o + 3]!;
      // ||x − c| − r| = |d² − r²| / (|x − c| + r).
      const b = Math.abs(d2 - r2) / (Math.sqrt(d2) + Math.sqrt(r2));
      delta = m === last ? b : Math.min(delta, b);
      if (d2 < r2) {
        applied = o;
        if (m < last) {
          invertWalk(st, rows[o]!, rows[o + 1]!, rows[o + 2]!, r2);
        }
        break;
      }
    }
    if (m === last) delta = Math.max(applied < 0 ? 0 : delta, seed, 0);
    else if (applied < 0) return floor;
    bound = Math.min(bound, carried(delta, s, r));
    // The minimum only falls: once it is at the caller's other bound, the rest cannot matter.
    if (bound <= floor) return floor;
  }
  return bound;
}
