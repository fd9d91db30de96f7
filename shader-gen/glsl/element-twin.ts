/**
 * The GLSL twin of an element kind (shader-gen/elements/<kind>.glsl.ts), mirroring the CPU kind in
 * <kind>.ts function by function. An element's data is packed into whole vec4s of `u_el` (layout
 * documented next to each twin). The generated loop holds one straight-line block per element,
 * specialised to its kind (no runtime switch); `inside` and `boundaryDistance` are functions.
 */
import type { SceneElement } from '../../nodes/core/scene.ts';
import type { GlslFunction } from './snippet.ts';

/**
 * The CPU `step` as statements placed in the IIS loop body, in their own scope, with the element's
 * data bound to `vec4 d0, d1, …` and the loop's `vec2 p`, `float s`, `int depth` in scope: when the
 * element applies they update p and s and `continue` (CPU: return true, the loop restarts);
 * otherwise they fall through (CPU: return false). The loop's increment counts an applied step as
 * 1 deep; a step worth n (n ≥ 1, a fold by n periods) adds the other n − 1 itself and never
 * less than 0, even on NaN: runIis loops while depth < maxIter with no second counter. Inline
 * rather than a function returning bool: SwiftShader does not inline such calls, and the inline
 * block runs about twice as fast there. Prefer arithmetic (min, step) to `if` and `?:` inside a
 * block: SwiftShader runs every branch and pays dearly for a select (inversion.ts CENTRE_GUARD).
 */
export interface GlslStepBlock {
  readonly code: string;
  /** The functions the block calls. */
  readonly deps: readonly GlslFunction[];
}

export const glslStepBlock = (code: string, deps: readonly GlslFunction[] = []): GlslStepBlock => ({
  code: code.trim(),
  deps,
});

export interface GlslElementTwin<E extends SceneElement = SceneElement> {
  readonly kind: E['kind'];
  /** vec4s of `u_el` per element of this kind. */
  readonly vec4s: number;
  /** The element's data, flattened: exactly 4 × vec4s numbers. */
  pack(e: E): number[];
  /** CPU `step`, inline (see GlslStepBlock). */
  readonly step: GlslStepBlock;
  /** `bool <kind>Inside(vec2 p, vec4 d0, …)`: CPU `inside`. */
  readonly inside: GlslFunction;
  /** `float <kind>BoundaryDistance(vec2 p, vec4 d0, …)`: CPU `boundaryDistance`. */
  readonly boundaryDistance: GlslFunction;
}
