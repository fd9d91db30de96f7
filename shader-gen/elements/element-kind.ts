/**
 * The contract of an element kind: its CPU step (the reference semantics of docs/math.md) and, beside
 * it, its GLSL twin. The IIS loop (interpret.ts, and the generated shader) calls `step` for each
 * element in graph order and restarts from the first element after every application.
 */
import type { SceneElement } from '../../nodes/core/scene.ts';

/** Mutable state of one IIS run: the point, the accumulated length scale and the step count. */
export interface IisState {
  x: number;
  y: number;
  /** Product of the conformal factors |g'(p)| along the path (docs/math.md "Length scale"). */
  s: number;
  depth: number;
}

export interface ElementKind<E extends SceneElement = SceneElement> {
  readonly kind: E['kind'];
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
