/**
 * Support for the closed-form element tests: run one element's `step` until it stops (what the IIS
 * loop does with a single element) and compare with a stepwise reference that applies the
 * single-step map repeatedly until the point is in the tile.
 */
import type { SceneElement } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { IisState } from '../../../shader-gen/elements/element-kind.ts';
import { elementRecord } from '../../../shader-gen/elements/index.ts';

export interface Folded {
  readonly p: Vec2;
  readonly depth: number;
  readonly s: number;
}

/** Repeats the kind's step while it applies (at most `limit` calls). */
export function foldWithKind(e: SceneElement, p: Vec2, limit = 1000): Folded & { calls: number } {
  const kind = elementRecord(e).cpu;
  const st: IisState = { x: p[0], y: p[1], s: 1, depth: 0 };
  let calls = 0;
  while (calls < limit && kind.step(e, st)) calls++;
  return { p: [st.x, st.y], depth: st.depth, s: st.s, calls };
}

/**
 * The stepwise reference: `single(p)` returns the next point and its scale factor, or null when p
 * is in the tile.
 */
export function foldStepwise(
  p: Vec2,
  single: (p: Vec2) => { p: Vec2; s: number } | null,
  limit = 1000,
): Folded {
  let q = p;
  let s = 1;
  let depth = 0;
  for (; depth < limit; depth++) {
    const next = single(q);
    if (!next) break;
    q = next.p;
    s *= next.s;
  }
  return { p: q, depth, s };
}

/** Whether x is within eps of an integer (a point too close to a tile edge to compare folds). */
export const nearInteger = (x: number, eps = 1e-7): boolean => Math.abs(x - Math.round(x)) < eps;
