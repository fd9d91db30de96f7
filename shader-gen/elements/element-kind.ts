/**
 * The contract of an element kind: ONE record (shader-gen/elements/<kind>.ts) holding its CPU step
 * (the reference semantics of docs/math.md) and, beside it, its GLSL twin, mirroring the CPU half
 * function by function. The IIS loop (interpret.ts, and the generated shader) calls `step` for each
 * element in graph order and restarts from the first element after every application.
 */
import type { SceneElement } from '../../nodes/core/scene.ts';
import type { GlslFunction } from '../glsl/snippet.ts';

/** Mutable state of one IIS run: the point, the accumulated length scale and the step count. */
export interface IisState {
  x: number;
  y: number;
  /** Product of the conformal factors |g'(p)| along the path (docs/math.md "Length scale"). */
  s: number;
  depth: number;
}

/** The CPU half: the reference the GPU is tested against. */
export interface CpuElement<E extends SceneElement = SceneElement> {
  /**
   * If the point is inside the element, applies it: updates x, y, s (scale taken at the point
   * before the map) and depth (+1, or +|k| for closed forms) and returns true. Else returns false
   * and leaves the state untouched.
   */
  step(e: E, st: IisState): boolean;
  /** Whether the element's inside holds (x, y): step would apply. */
  inside(e: E, x: number, y: number): boolean;
  /**
   * Euclidean distance from (x, y) to the nearest boundary of the element's inside region(s):
   * where a float32 GPU and the float64 CPU may disagree about "inside".
   */
  boundaryDistance(e: E, x: number, y: number): number;
}

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

/**
 * The GLSL half. An element's data is packed into whole vec4s of `u_el` (layout documented next to
 * each kind), or written as `vec4(…)` literals in a baked program (glsl/values.ts places them
 * either way). The generated loop holds one straight-line block per element, specialised to its
 * kind (no runtime switch); `inside` and `boundaryDistance` are functions.
 */
export interface GlslElement<E extends SceneElement = SceneElement> {
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

/** One element kind: both halves, neither optional (a kind without its twin does not type-check). */
export interface ElementRecord<E extends SceneElement = SceneElement> {
  readonly kind: E['kind'];
  readonly cpu: CpuElement<E>;
  readonly glsl: GlslElement<E>;
}
