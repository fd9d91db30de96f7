/**
 * The contract of a 3D element kind, mirroring shader-gen/elements/element-kind.ts one dimension
 * up: ONE record per kind (shader-gen/space/elements/<kind>.ts) holding its CPU step (the
 * reference) and its GLSL twin. The sphere tracer's walk (walk.ts and its GLSL twin) calls `step`
 * for each element in scene order and restarts from the first after every application.
 *
 * The distance bound needs, besides the point and its conformal factor, where the composed map
 * sends ∞ — its pole (docs/math-3d.md "§8 The tracer's distance bound"). When the walk tracks it,
 * every step moves the pole by the same map as the point. ∞ is stood for by the point POLE_AT_INFINITY
 * (10¹⁸ away: an inversion sends it to within r²·10⁻¹⁸ of its centre, squared it still fits float32,
 * and isometries keep it 10¹⁸ away), so no step needs a case for it.
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
  /** The pole of the composed map (where ∞ went), or null when the walk does not track it. */
  pole: Pole3d | null;
}

export interface Pole3d {
  x: number;
  y: number;
  z: number;
}

/** The pole before any step: a stand-in for ∞ (see above). */
export const POLE_AT_INFINITY = 1e18;

/** What the walk needs a GLSL step to emit beyond moving `p`. */
export interface StepHooks {
  /** Also move `vec3 pole` by the same map. */
  readonly pole: boolean;
  /** A statement run when the element applies, just before its `continue` ('' for none). */
  readonly applied: string;
}

export interface CpuElement3d<E extends Element3d = Element3d> {
  /** If the point lies in the element's region: moves it (factor, depth + 1) and returns true. */
  step(e: E, st: Walk3dState): boolean;
  /**
   * Distance from (x, y, z) to the element's region(s) (0 inside): the fallback cover of the orbit
   * inside the regions (docs/math-3d.md §7).
   */
  regionDistance(e: E, x: number, y: number, z: number): number;
  /**
   * The cover at the walk's final point only, where it differs from `regionDistance`: a fold that
   * brings every point of its region nearer to each point outside it (the box fold) needs no cover
   * there, since its region's orbit is never nearer than the orbit outside the region
   * (docs/math-3d.md §10). The mirrored cover's L at the image p* keeps `regionDistance`.
   */
  endCover?(e: E, x: number, y: number, z: number): number;
  /**
   * Elements that are one involution (a sphere inversion, a plane reflection): the image of a point
   * in `out` (x, y, z) and the r² of the inversion (0: an isometry), for the mirrored cover of the
   * bound (docs/math-3d.md "§8 The tracer's distance bound"). Absent for the other kinds.
   */
  mirror?(e: E, x: number, y: number, z: number, out: Walk3dState): number;
  /**
   * A lower bound of the distance from (x, y, z) to the boundary of the element's region, on either
   * side, for the bound of a walk that ran out of budget (docs/math-3d.md "The bound when the budget
   * runs out"). Absent: that bound is not formed for scenes with the kind.
   */
  boundaryDistance?(e: E, x: number, y: number, z: number): number;
}

export interface GlslElement3d<E extends Element3d = Element3d> {
  /** vec4 rows of element data. */
  readonly vec4s: number;
  /** The element's data, flattened: exactly 4 × vec4s numbers. */
  pack(e: E): number[];
  /**
   * The CPU `step` as statements in the walk loop, with `vec4 d0, d1, …` bound to its data and
   * `vec3 p`, `float s`, `int depth` (and, with `hooks.pole`, `vec3 pole`) in
   * scope; when it applies it ends with `hooks.applied` and `continue`.
   */
  step(hooks: StepHooks): string;
  /** `float <kind>RegionDistance(vec3 p, vec4 d0, …)`: CPU `regionDistance`. */
  readonly regionDistance: GlslFunction;
  /** `float <kind>EndCover(vec3 p, vec4 d0, …)`: the CPU `endCover`, where it has one. */
  readonly endCover?: GlslFunction;
  /**
   * The CPU `mirror`: `float <kind>Mirror(vec3 p, vec4 d0, …, out vec3 q, out float far)` sets q to
   * the image and far to |q − c|, and returns r² (0: an isometry).
   */
  readonly mirror?: GlslFunction;
  /**
   * The CPU `boundaryDistance`: `float <kind>BoundaryDistance(vec3 p, vec4 d0, …)`, for the bound
   * of a walk that ran out of budget (../glsl/budget.glsl.ts). Absent: as on the CPU, that bound is
   * not formed for scenes with the kind.
   */
  readonly boundaryDistance?: GlslFunction;
  /** Functions the step block calls. */
  readonly deps: readonly GlslFunction[];
}

export interface ElementRecord3d<E extends Element3d = Element3d> {
  readonly kind: E['kind'];
  readonly cpu: CpuElement3d<E>;
  readonly glsl: GlslElement3d<E>;
}

/** The end of a GLSL step block that applied: count it, run the walk's hook, restart the loop. */
export const appliedGlsl = (applied: string): string =>
  ['  depth += 1;', ...(applied ? [`  ${applied}`] : []), '  continue;'].join('\n');
