/**
 * The bound of a walk that ran out of budget (shader-gen/space/budget-bound.ts, docs/math-3d.md
 * "The bound when the budget runs out"), brute force: with the tile as the seed and max iterations
 * N (Figs. 27–28 a–d), no point the tracer draws — one whose IIS (nodes' own iis3d, not the
 * tracer's walk) ends inside the tile within N steps — lies in the ball the bound claims empty.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { sampleSpace } from '../../../nodes/core/seed-3d.ts';
import { add3, scale3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { budgetBound } from '../../../shader-gen/space/budget-bound.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { walk3d } from '../../../shader-gen/space/walk.ts';
import { SEED } from '../../nodes/geometry/space/arbitraries.ts';
import { PROBES, SHELLS } from './orbit-probe.ts';
import { exampleScenes3d } from './scenes-3d.ts';

/** Drawn with budget N: the walk ends inside a seed (at any step ≤ N, escaped or not). */
const drawn = (scene: Scene3d, p: Vec3): boolean => {
  const s = sampleSpace(scene, p);
  return s.distance !== null && s.distance < 0;
};

/** The smallest shell (× b) whose probes meet the drawn set, else ∞. */
function drawnWithin(scene: Scene3d, x: Vec3, b: number): number {
  for (const rho of SHELLS) for (const p of PROBES) if (drawn(scene, add3(x, scale3(p, rho * b)))) return rho;
  return Number.POSITIVE_INFINITY;
}

/** The Fig. 27 (finite tile) scene with budget n. */
const FIG27 = exampleScenes3d()['fig27-tiling-steps']!;
const fig27 = (n: number): Scene3d => ({ ...FIG27, maxIterations: n });

describe('the bound when the budget runs out (docs/math-3d.md)', () => {
  const cases = fc.record({
    n: fc.constantFrom(1, 2, 3, 5),
    u: fc.tuple(
      fc.double({ min: -1, max: 1 }),
      fc.double({ min: -1, max: 1 }),
      fc.double({ min: -1, max: 1 }),
    ),
  });

  it('leaves no drawn point in the ball it claims empty, and the drawn set is met a few bounds away', () => {
    let tested = 0;
    let nearby = 0;
    for (const c of fc.sample(cases, { seed: SEED.seed, numRuns: 2000 })) {
      const scene = fig27(c.n);
      const plan = prepareTrace3d(scene);
      const { center, radius } = plan.bounds;
      const x = add3(center, scale3(c.u, 0.7 * radius)) as Vec3;
      const w = walk3d(plan, ...x, true);
      if (w.escaped || w.imageDistance < 0) continue;
      const b = budgetBound(plan, ...x, w.imageDistance * w.factor);
      if (!(b > 1e-9)) continue;
      tested++;
      // The walk's bound is at least this one (it takes the larger of §8's and this).
      expect(w.de).toBeGreaterThanOrEqual(b * (1 - 1e-9));
      const found = drawnWithin(scene, x, b);
      expect(found).toBeGreaterThan(0.99);
      if (found <= 10) nearby++;
      if (tested >= 40) break;
    }
    expect(tested).toBeGreaterThan(30);
    // Tight enough that a bound a few times too large would fail: most points see the drawn set
    // within 10 bounds.
    expect(nearby).toBeGreaterThan(tested / 2);
  }, 300_000);
});
