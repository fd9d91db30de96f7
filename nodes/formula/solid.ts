/**
 * A 3D seed written as a formula (docs/formula.md "3D seed shapes"): f(x, y, z) of the point
 * relative to the seed's centre and the numbers a, b, c, negative inside. The tracer needs a
 * distance bound, not only a sign: it takes
 *   inside the ball:  d(p) = max(f(p − c) / L, b),        b = |p − c| − R ≤ 0,
 *   outside it:       d(p) = max(b, f(p′ − c) / L − b),    p′ = p pulled onto the ball's sphere,
 * the formula divided by its slope bound L (1 when f is a true distance, i.e. 1-Lipschitz) and cut
 * to the bounding ball of radius R. If |f(u) − f(v)| ≤ L·|u − v| in the ball and f = 0 on the
 * surface, then from a point of the ball |f| / L ≤ the distance to the surface (the shortest path
 * to the solid stays in the convex ball), and the distance to an intersection is at least the
 * larger of the two bounds. Outside the ball f is not known to be tame, so it is read at p′ only:
 * dist(p, S) ≥ dist(p′, S) − |p − p′| = dist(p′, S) − b, and dist(p, S) ≥ b. So d never
 * overshoots (docs/math-3d.md §8 needs no more), and it is positive on the ball's sphere wherever
 * the solid is not, so the bounding ball itself is never drawn. L is not proven for a formula people type: `sampledSlope` measures it, and the node
 * warns (KF330) and divides by more than it measured when it exceeds 1.
 */
import type { Seed3d } from '../core/scene-3d.ts';
import { numberRun } from './checked.ts';
import type { FormulaValue } from './functions.ts';
import { SOLID_NAMES } from './names.ts';

type SolidSeed = Extract<Seed3d, { kind: 'formula' }>;
type Run = (env: Record<string, FormulaValue>) => FormulaValue;

/** The run function of a solid formula, or null for one that does not check (the node says why). */
export const solidRun = (text: string): Run | null => numberRun(text, SOLID_NAMES);

/** One scratch environment, refilled per call (each renderer thread has its own module copy). */
const env: Record<string, number> = { a: 0, b: 0, c: 0, x: 0, y: 0, z: 0 };

/** f(x, y, z) with a, b, c: the formula at a point relative to the seed's centre. */
export function solidValue(run: Run, abc: readonly number[], x: number, y: number, z: number): number {
  env.a = abc[0]!;
  env.b = abc[1]!;
  env.c = abc[2]!;
  env.x = x;
  env.y = y;
  env.z = z;
  return run(env) as number;
}

const runs = new WeakMap<SolidSeed, Run | null>();

/** The seed's distance bound at (x, y, z): max(f(p − c)/L, |p − c| − R) (see the top). */
export function solidSeedDistance(seed: SolidSeed, x: number, y: number, z: number): number {
  let run = runs.get(seed);
  if (run === undefined) {
    run = solidRun(seed.formula);
    runs.set(seed, run);
  }
  const u = x - seed.center[0];
  const v = y - seed.center[1];
  const w = z - seed.center[2];
  const len = Math.sqrt(u * u + v * v + w * w);
  const ball = len - seed.radius;
  if (!run) return ball;
  if (ball < 0) {
    const f = solidValue(run, seed.numbers, u, v, w) / seed.slope;
    // NaN (a formula undefined there) counts as on the surface: 0, never an overshoot.
    return f > ball ? f : Number.isNaN(f) ? 0 : ball;
  }
  // Outside the ball the slope is not known: the formula is read at p′, p pulled onto the sphere.
  const k = seed.radius / Math.max(len, 1e-300);
  const fs = solidValue(run, seed.numbers, u * k, v * k, w * k) / seed.slope;
  return fs - ball > ball ? fs - ball : ball;
}

/** Sample points per axis of the slope check's grid (its cube is clipped to the ball). */
const SLOPE_GRID = 10;

export interface SlopeCheck {
  /** Largest |∇f| seen (central differences), 0 when nothing finite was seen. */
  readonly slope: number;
  /** Whether f was negative anywhere sampled: false means the seed is (probably) empty. */
  readonly inside: boolean;
  /** A sampled point (relative to the centre) where f is not a number, or null. */
  readonly undefinedAt: readonly [number, number, number] | null;
}

/**
 * Samples |∇f| on a SLOPE_GRID³ grid over the ball of radius R (central differences of step
 * R / 1000) and whether f < 0 anywhere there. A sample, not a proof: the node divides by more
 * than the largest slope seen.
 */
export function sampledSlope(run: Run, abc: readonly number[], radius: number): SlopeCheck {
  const h = radius / 1000;
  let slope = 0;
  let inside = false;
  let undefinedAt: [number, number, number] | null = null;
  for (let i = 0; i < SLOPE_GRID; i++)
    for (let j = 0; j < SLOPE_GRID; j++)
      for (let k = 0; k < SLOPE_GRID; k++) {
        const x = radius * ((2 * i + 1) / SLOPE_GRID - 1);
        const y = radius * ((2 * j + 1) / SLOPE_GRID - 1);
        const z = radius * ((2 * k + 1) / SLOPE_GRID - 1);
        if (x * x + y * y + z * z > radius * radius) continue;
        const f = solidValue(run, abc, x, y, z);
        if (f < 0) inside = true;
        if (Number.isNaN(f) && !undefinedAt) undefinedAt = [x, y, z];
        const gx = solidValue(run, abc, x + h, y, z) - solidValue(run, abc, x - h, y, z);
        const gy = solidValue(run, abc, x, y + h, z) - solidValue(run, abc, x, y - h, z);
        const gz = solidValue(run, abc, x, y, z + h) - solidValue(run, abc, x, y, z - h);
        const g = Math.sqrt(gx * gx + gy * gy + gz * gz) / (2 * h);
        if (g > slope) slope = g; // NaN never passes the test
      }
  return { slope, inside, undefinedAt };
}
