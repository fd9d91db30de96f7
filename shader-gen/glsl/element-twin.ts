/**
 * The GLSL twin of an element kind (shader-gen/elements/<kind>.glsl.ts), mirroring the CPU kind in
 * <kind>.ts function by function. An element's data is packed into whole vec4s of `u_el` (layout
 * documented next to each twin); the generated loop calls the twin's functions with those vec4s
 * as the trailing arguments, straight-line code specialised to the kind (no runtime switch).
 */
import type { SceneElement } from '../../nodes/core/scene.ts';
import type { GlslFunction } from './snippet.ts';

export interface GlslElementTwin<E extends SceneElement = SceneElement> {
  readonly kind: E['kind'];
  /** vec4s of `u_el` per element of this kind. */
  readonly vec4s: number;
  /** The element's data, flattened: exactly 4 × vec4s numbers. */
  pack(e: E): number[];
  /** `bool <kind>Step(inout vec2 p, inout float s, inout int depth, vec4 d0, …)`: CPU `step`. */
  readonly step: GlslFunction;
  /** `bool <kind>Inside(vec2 p, vec4 d0, …)`: CPU `inside`. */
  readonly inside: GlslFunction;
  /** `float <kind>BoundaryDistance(vec2 p, vec4 d0, …)`: CPU `boundaryDistance`. */
  readonly boundaryDistance: GlslFunction;
}
