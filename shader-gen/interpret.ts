/**
 * The CPU reference of the IIS loop (docs/math.md, normative), in float64:
 *   depth = 0; s = 1
 *   repeat: e = first element (graph order) whose inside holds p
 *           none → escaped; depth == maxIter → not escaped; else s *= scale_e(p); p = e(p); depth += 1
 * Written as: at depth ≥ maxIter only ask whether some element holds p; otherwise step the first
 * element that holds p and restart. The generated shader has exactly this shape.
 */
import type { Scene, SceneElement } from '../nodes/core/scene.ts';
import type { Vec2 } from '../nodes/core/values.ts';
import type { CpuElement, IisState } from './elements/element-kind.ts';
import { ELEMENTS } from './elements/index.ts';

export interface IisResult {
  readonly depth: number;
  /** The final point (in the tile when escaped). */
  readonly final: Vec2;
  readonly escaped: boolean;
  /** Accumulated length scale s along the path. */
  readonly scale: number;
}

/** The elements with their kinds looked up once (hot loops call this per image, not per point). */
export interface PreparedElements {
  readonly elements: readonly SceneElement[];
  readonly kinds: readonly CpuElement<SceneElement>[];
}

export function prepare(elements: readonly SceneElement[]): PreparedElements {
  return {
    elements,
    kinds: elements.map((e) => ELEMENTS[e.kind].cpu as unknown as CpuElement<SceneElement>),
  };
}

/**
 * Runs the loop on `st` in place; returns whether the point escaped (reached the tile). A closed-form
 * element may add several steps at once, so depth can pass maxIter by that last fold. `visit`, when
 * given, sees the state at the start of every pass (every point of the path, the final one included)
 * with the index of the element whose step led there (−1 at the start point); when it returns true
 * the run stops there, not escaped (orbit seeds: docs/math.md "tested at the start of every step").
 * It is the one observer of the loop: raster.ts stops at seeds with it, path-margin.ts measures the
 * path and trace.ts records every step, so none of them runs a copy of the loop.
 */
export function runIis(
  prepared: PreparedElements,
  maxIter: number,
  st: IisState,
  visit?: (st: IisState, applied: number) => boolean | undefined,
): boolean {
  const { elements, kinds } = prepared;
  const n = elements.length;
  let applied = -1;
  for (;;) {
    if (visit?.(st, applied) === true) return false;
    if (st.depth >= maxIter) {
      for (let i = 0; i < n; i++) if (kinds[i].inside(elements[i], st.x, st.y)) return false;
      return true;
    }
    let i = 0;
    while (i < n && !kinds[i].step(elements[i], st)) i++;
    if (i === n) return true;
    applied = i;
  }
}

export function interpret(scene: Pick<Scene, 'elements' | 'maxIterations'>, p: Vec2): IisResult {
  const st: IisState = { x: p[0], y: p[1], s: 1, depth: 0 };
  const escaped = runIis(prepare(scene.elements), scene.maxIterations, st);
  return { depth: st.depth, final: [st.x, st.y], escaped, scale: st.s };
}
