/**
 * Helpers shared by the construction, generator and kaleidoscope node files added with the full
 * mathematics: direction inputs in degrees and draggable handles on point inputs.
 */
import type { InputSpec } from '../core/define-node.ts';
import type { Line, Vec2 } from '../core/values.ts';
import { add } from '../geometry/vec.ts';

/** A direction input in degrees, counter-clockwise from +x. */
export const angleInput = (label: string, dflt: number, doc: string) =>
  ({ type: 'number', label, default: dflt, step: 1, doc }) as const satisfies InputSpec;

/** Unit vector (cos t, sin t) for t in degrees. */
export const unitFromDegrees = (deg: number): Vec2 => {
  const t = (deg * Math.PI) / 180;
  return [Math.cos(t), Math.sin(t)];
};

/** Direction of v in degrees, atan2(v_y, v_x)·180/π, rounded to 0.01° (handles write clean values). */
export const degreesOf = (v: Vec2): number => Math.round((Math.atan2(v[1], v[0]) * 18000) / Math.PI) / 100;

/** The line through p with direction d (for overlays): a = p, b = p + d. */
export const lineAlong = (p: Vec2, d: Vec2): Line => ({ a: p, b: add(p, d) });

/**
 * Handles on a node's point inputs: each sits at the input's value and a drag writes the new
 * point back (a wired input drags its source, see NodeDef.drag).
 */
export function pointHandles<const K extends string>(...keys: K[]) {
  return {
    handles: (ctx: { readonly inputs: { readonly [k in K]: Vec2 } }) =>
      keys.map((k) => ({ handle: k, at: ctx.inputs[k] })),
    drag: (handle: string, to: Vec2) => ({ [handle]: [...to] }),
  };
}
