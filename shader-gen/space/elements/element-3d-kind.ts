/**
 * The contract of a 3D element kind, mirroring shader-gen/elements/element-kind.ts one dimension
 * up: ONE record per kind (shader-gen/space/elements/<kind>.ts) holding its CPU step (the
 * reference) and its GLSL twin. The sphere tracer's walk (walk.ts and its GLSL twin) calls `step`
 * for each element in scene order and restarts from the first after every application.
 *
 * Every inversion a step applies is reported to `push(r², far)` BEFORE the point moves (far =
 * |x' − c|, the distance of the image from the centre): the walk keeps one record per inversion on
 * a per-ray stack and folds the distance bound back through them (docs/math-3d.md "§8 The tracer's distance bound"). Isometries
 * (plane reflections, the compound parabolic) push nothing: they keep distances.
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import type { GlslFunction } from '../../glsl/snippet.ts';

/** Mutable state of one walk: the point, the accumulated conformal factor and the step count. */
export interface Walk3dState {
  x: number;
  y: number;
  z: number;
  /** Product of the conformal factors along the path (lengths at the start scale by this). */
  s: number;
  depth: number;
}

/** Receives one inversion (its r² and the image's distance |x' − c| from the centre); null: not recording. */
export type PushInversion = ((r2: number, far: number) => void) | null;

export interface CpuElement3d<E extends Element3d = Element3d> {
  /** If the point lies in the element's region: moves it (factor, depth + 1) and returns true. */
  step(e: E, st: Walk3dState, push: PushInversion): boolean;
  /**
   * Distance from (x, y, z) to the element's region(s) (0 inside): the fallback cover of the orbit
   * inside the regions (docs/math-3d.md §7).
   */
  regionDistance(e: E, x: number, y: number, z: number): number;
  /**
   * Elements that are one involution (a sphere inversion, a plane reflection): the image of a point
   * in `out` (x, y, z) and the r² of the inversion (0: an isometry), for the mirrored cover of the
   * bound (docs/math-3d.md "§8 The tracer's distance bound"). Absent for the other kinds.
   */
  mirror?(e: E, x: number, y: number, z: number, out: Walk3dState): number;
}

export interface GlslElement3d<E extends Element3d = Element3d> {
  /** vec4 rows of element data. */
  readonly vec4s: number;
  /** The element's data, flattened: exactly 4 × vec4s numbers. */
  pack(e: E): number[];
  /**
   * The CPU `step` as statements in the walk loop, with `vec4 d0, d1, …` bound to its data and
   * `vec3 p`, `float s`, `int depth` in scope; when it applies it ends with `continue`. `push(r2,
   * far)` gives the statement that records an inversion ('' when the walk does not record).
   */
  step(push: (r2: string, far: string) => string): string;
  /** `float <kind>RegionDistance(vec3 p, vec4 d0, …)`: CPU `regionDistance`. */
  readonly regionDistance: GlslFunction;
  /**
   * The CPU `mirror`: `float <kind>Mirror(vec3 p, vec4 d0, …, out vec3 q, out float far)` sets q to
   * the image and far to |q − c|, and returns r² (0: an isometry).
   */
  readonly mirror?: GlslFunction;
  /** Functions the step block calls. */
  readonly deps: readonly GlslFunction[];
}

export interface ElementRecord3d<E extends Element3d = Element3d> {
  readonly kind: E['kind'];
  /** The most inversions one application records (the stack must have room for them). */
  readonly inversionsPerStep: number;
  readonly cpu: CpuElement3d<E>;
  readonly glsl: GlslElement3d<E>;
}
