/**
 * The GLSL twin of ../budget-bound.ts (docs/math-3d.md "The bound when the budget runs out"): when
 * the walk of x ran out of its N steps, the tracer draws only T_N, the points whose walk reaches a
 * seed within N steps, and §8's bound of the whole orbit is far too small near the limit set. The
 * walk is re-run from x, and at every step m, before the step moves anything,
 *
 *   δ_m = min over the elements tested at x_m up to the one applied of dist(x_m, ∂region_i)
 *   δ_N = max(the applied element's boundary distance at x_N, seed distance at x_N, 0)
 *   bound = min over m ≤ N of δ_m / (s_m·(1 + δ_m/R_m)),   R_m = |x_m − P_m|,
 *
 * returned as max(bound, floor), floor being §8's bound (the caller's); the walk stops as soon as
 * the minimum reaches the floor. Only scenes whose every element kind has a boundary distance (sphere
 * inversions, plane reflections) have it, as on the CPU. One straight-line block per element, as in
 * the walk itself (walk.glsl.ts); the element's own step code moves the point, the pole and the
 * factor, and the hook it runs when it applies forms that step's term.
 */
import { GLSL_FAR } from '../../glsl/iis.glsl.ts';
import { floatLiteral } from '../../glsl/literal.ts';
import type { GlslFunction } from '../../glsl/snippet.ts';
import type { SourceBuilder } from '../../glsl/source.ts';
import { POLE_AT_INFINITY } from '../elements/element-3d-kind.ts';
import type { TracePlan } from '../plan.ts';
import { emitStepBlocks, type PlacedWalk, walkLimit } from './placed-walk.ts';

/**
 * Whether the program has the bound: every element kind has a GLSL boundary distance (as on the
 * CPU), and a seed is a sphairahedron's tile — the tiling steps of Figs. 27–28, whose max
 * iterations N is a step count that stops far from the orbit, so that without the bound the march
 * runs out of steps long before the drawn set (Fig. 28 (b)–(d): 65 % and 34 % agreement with the
 * CPU). Elsewhere the GPU leaves it out: the second walk's code alone, even never run, made Figs.
 * 11, 26 and 37 1.6–2.1× slower in SwiftShader (`npm run bench`), and §8's bound alone reaches their
 * surfaces; both bounds are safe, so the pictures agree with the CPU's either way.
 */
export const budgetBoundIn = (plan: TracePlan): boolean =>
  plan.records.length > 0 &&
  plan.records.every((record) => record.glsl.boundaryDistance) &&
  plan.scene.seeds.some((seed) => seed.kind === 'tile');
export const hasBudgetBound = (placed: PlacedWalk): boolean => budgetBoundIn(placed.plan);

/** The boundary-distance functions the budget walk calls. */
export const budgetFunctions = (placed: PlacedWalk): GlslFunction[] =>
  hasBudgetBound(placed) ? placed.elements.map(({ record }) => record.glsl.boundaryDistance!) : [];

/** A step's term: δ/(s·(1 + δ/R)) with the factor and pole distance before the step. */
const term = (delta: string, s: string, r: string) => `${delta} / (${s} * (1.0 + ${delta} / ${r}))`;

/**
 * `float walkBudget(vec3 start, float seedDe, float floorDe)`: the bound above for a walk from
 * `start` that did not escape; seedDe is min over seeds of the seed distance at its final point.
 * And `float budgetedDe(vec3 start, vec4 info, float de)`: walkRecord's `de` raised by it when that
 * walk (its `info`) ran out of budget.
 */
export function emitBudgetWalk(out: SourceBuilder, placed: PlacedWalk): void {
  const limit = walkLimit(placed);
  // Run when an element applies (after its step moved p, s and the pole, and depth += 1).
  const applied = [
    `bound = min(bound, ${term('(last ? max(max(b, seedDe), 0.0) : delta)', 'sm', 'r')});`,
    'if (last || bound <= floorDe) return max(bound, floorDe);',
  ].join(' ');
  out.push(
    'float walkBudget(vec3 start, float seedDe, float floorDe) {',
    '  vec3 p = start;',
    '  float s = 1.0;',
    '  int depth = 0;',
    `  vec3 pole = vec3(${floatLiteral(POLE_AT_INFINITY)}, 0.0, 0.0);`,
    `  float bound = ${GLSL_FAR};`,
    `  for (; depth <= ${limit};) {`,
    `    bool last = depth == ${limit};`,
    '    float r = length(p - pole);',
    '    float sm = s;',
    `    float delta = ${GLSL_FAR};`,
    '    float b;',
  );
  emitStepBlocks(out, placed, { pole: true, applied }, (record, args) => [
    `b = ${record.glsl.boundaryDistance!.name}(p, ${args});`,
    'delta = min(delta, b);',
  ]);
  out.push(
    // No element applied: the walk escaped after all (before N: no bound), or x_N is in no region.
    `    if (last) return max(min(bound, ${term('max(seedDe, 0.0)', 's', 'length(p - pole)')}), floorDe);`,
    '    return floorDe;',
    '  }',
    '  return max(bound, floorDe);',
    '}',
    '',
    // info = (seed-image distance, depth, seed, factor) of walkRecord: out of budget when depth = N.
    'float budgetedDe(vec3 start, vec4 info, float de) {',
    `  return info.y >= float(${limit}) ? walkBudget(start, info.x * info.w, de) : de;`,
    '}',
    '',
  );
}
