/**
 * How close an IIS run comes to deciding differently: the minimum over every point of its path
 * of (distance to the nearest element boundary) / s, where s is the length scale accumulated so
 * far — the distance measured back in the original coordinates (docs/math.md "Length scale"). Where
 * this is below the rounding error of the arithmetic (float32 on GPUs), a GPU and the float64 CPU
 * may legitimately take different branches; the parity test excludes those samples.
 */
import type { Vec2 } from '../nodes/core/values.ts';
import type { IisState } from './elements/element-kind.ts';
import { type IisResult, type PreparedElements, runIis } from './interpret.ts';

export interface MarginResult extends IisResult {
  /** min over the path of min_e boundaryDistance_e(p_k) / s_k (world units at the start point). */
  readonly margin: number;
}

export function pathMargin(prepared: PreparedElements, maxIter: number, p: Vec2): MarginResult {
  const { elements, kinds } = prepared;
  const st: IisState = { x: p[0], y: p[1], s: 1, depth: 0 };
  let margin = Number.POSITIVE_INFINITY;
  const escaped = runIis(prepared, maxIter, st, (at) => {
    for (let i = 0; i < elements.length; i++) {
      margin = Math.min(margin, kinds[i].boundaryDistance(elements[i], at.x, at.y) / at.s);
    }
    return undefined;
  });
  return { depth: st.depth, final: [st.x, st.y], escaped, scale: st.s, margin };
}
