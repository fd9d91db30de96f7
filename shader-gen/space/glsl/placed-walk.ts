/**
 * Where the GLSL walk's data lives (walk.glsl.ts, budget.glsl.ts): every element's, content ball's
 * and seed's rows as `u_el` uniform rows or literals (baked), the globals `el<N>` they are copied
 * into once per pixel, and the step budget.
 */
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import type { SourceBuilder } from '../../glsl/source.ts';
import { ELEMENT_ARRAY, type SceneValues } from '../../glsl/values.ts';
import type { ElementRecord3d, StepHooks } from '../elements/element-3d-kind.ts';
import type { TracePlan } from '../plan.ts';
import { packSeed } from '../seeds-3d.ts';

export interface PlacedWalk {
  readonly plan: TracePlan;
  readonly elements: readonly {
    readonly record: ElementRecord3d;
    readonly rows: readonly string[];
    /** Content-ball row (c, r) and (reach, 0, 0, 0), for sphere inversions of all-inversion scenes. */
    readonly hull: readonly [string, string] | null;
  }[];
  /** Each seed's rows (../seeds-3d.ts packSeed: two for a sphere or box, nine for a tile). */
  readonly seeds: readonly (readonly string[])[];
  readonly maxIter: string;
}

/** The walk's step budget in GLSL: the literal when baked, else the `maxIter` global. */
export const walkLimit = (placed: PlacedWalk): string =>
  /^\d+$/.test(placed.maxIter) ? placed.maxIter : 'maxIter';

/** Places every element's, content ball's and seed's data (uniform rows or literals). */
export function placeWalk(plan: TracePlan, v: SceneValues): PlacedWalk {
  const scene: Scene3d = plan.scene;
  const elements = scene.elements.map((e, i) => {
    const record = plan.records[i]!;
    const data = record.glsl.pack(e as never);
    if (data.length !== 4 * record.glsl.vec4s)
      throw new Error(`${record.kind} packed ${data.length} numbers`);
    const rows = v.elementRows(data);
    const h = plan.hulls[i];
    const hull = h
      ? (v.elementRows([...h.center, h.radius, plan.reach[i]!, 0, 0, 0]) as [string, string])
      : null;
    return { record, rows, hull };
  });
  const seeds = scene.seeds.map((s) => v.elementRows(packSeed(s)));
  return { plan, elements, seeds, maxIter: v.int('u_maxIterations', scene.maxIterations) };
}

const UNIFORM_ROW = new RegExp(`^${ELEMENT_ARRAY}\\[(\\d+)\\]$`);
/** The local holding a row: `el<N>` for `u_el[N]`, the literal itself when baked. */
export const local = (expr: string): string => {
  const m = UNIFORM_ROW.exec(expr);
  return m ? `el${m[1]}` : expr;
};

/**
 * The walk loop's body: one straight-line block per element, in scene order — its rows bound to
 * `vec4 d0, d1, …`, then `before` (statements reading them, e.g. a boundary distance), then the
 * kind's own step with `hooks` (which ends in `continue` when it applies).
 */
export function emitStepBlocks(
  out: SourceBuilder,
  placed: PlacedWalk,
  hooks: StepHooks,
  before: (record: ElementRecord3d, args: string) => readonly string[] = () => [],
): void {
  placed.elements.forEach(({ record, rows }, i) => {
    const args = rows.map((_, k) => `d${k}`).join(', ');
    out.block(i + 1, [
      `    { // ${record.kind}`,
      ...rows.map((expr, k) => `      vec4 d${k} = ${local(expr)};`),
      ...before(record, args).map((line) => `      ${line}`),
      ...record.glsl
        .step(hooks)
        .split('\n')
        .map((line) => `      ${line}`),
      '    }',
    ]);
  });
}
