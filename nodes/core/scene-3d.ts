/**
 * The 3D Scene: what a `render-3d` node resolves to, the contract between the 3D nodes (which build
 * it), the CPU sphere tracer (the tested reference) and the GLSL sphere-tracing generator. Like the
 * 2D Scene it holds only numbers: every construction (four-point spheres, compound generators,
 * sphairahedra) is already done. Mathematics: docs/math-3d.md.
 *
 * A graph has at most one render node; when it is a `render-3d` node the evaluation's `scene3d`
 * is this and the 2D `scene` is empty (no elements), so 2D code never sees 3D data.
 */
import type { Element3d } from '../geometry/space/iis-3d.ts';
import type { SphairahedronTile } from '../geometry/space/sphairahedron-tile.ts';
import type { Plane, Sphere } from '../geometry/space/sphere.ts';
import type { Vec3 } from '../geometry/space/vec3.ts';
import type { LimitSet3d } from './limit-set-3d.ts';
import type { Color } from './values.ts';

export type { Element3d } from '../geometry/space/iis-3d.ts';
export type { Plane, Sphere } from '../geometry/space/sphere.ts';
export type { Vec3 } from '../geometry/space/vec3.ts';

/**
 * An element as a node outputs it: the id of the node that made it travels with it (messages name
 * that node, e.g. the element whose region holds a seed). A Scene3d's elements are these.
 */
export type NodeElement3d = Element3d & { readonly nodeId: string };

/**
 * An orbit seed in space (paper Figs. 11–12, 24): its images under the group are the surfaces the
 * tracer draws. `nodeId` names the node that made it (messages, handles).
 */
export type Seed3d = (
  | { readonly kind: 'sphere'; readonly nodeId: string; readonly sphere: Sphere; readonly color: Color }
  /** An axis-aligned box: centre and half-extents along x, y, z (Fig. 24, "orbit of a cube"). */
  | {
      readonly kind: 'box';
      readonly nodeId: string;
      readonly center: Vec3;
      readonly halfSize: Vec3;
      readonly color: Color;
    }
  /**
   * A solid written as a formula of x, y, z (relative to `center`) and a, b, c, negative inside,
   * kept within the ball of `radius` about the centre (docs/formula.md "3D seed shapes"). Its
   * distance is f / `slope` (slope ≥ 1: 1 for a true distance, more where the sampled check found
   * the formula steeper), cut to the ball.
   */
  | {
      readonly kind: 'formula';
      readonly nodeId: string;
      readonly center: Vec3;
      readonly radius: number;
      readonly formula: string;
      readonly numbers: readonly [number, number, number];
      readonly slope: number;
      readonly color: Color;
    }
  /** A sphairahedron's tile, its fundamental domain (Fig. 25; docs/math-3d.md "The tile as a seed"). */
  | {
      readonly kind: 'tile';
      readonly nodeId: string;
      readonly tile: SphairahedronTile;
      readonly color: Color;
    }
) & {
  /**
   * Set when only the seed's part in the fundamental domain is meant and it reaches into mirror
   * regions by design (the sphairahedron's half-space below its floor, docs/math-3d.md
   * "Sphairahedra (paper §5.3)"): the render does not warn that it is outside the domain.
   */
  readonly clipped?: true;
  /**
   * A mirror seed's reflectivity in [0, 1], Fresnel's F0 (docs/math-3d.md "Mirror material");
   * absent for a matte seed.
   */
  readonly reflectivity?: number;
};
export type Seed3dKind = Seed3d['kind'];

/** A pinhole camera looking from `position` at `target`; z is up; `fovDeg` is the vertical field of view. */
export interface Camera3d {
  readonly position: Vec3;
  readonly target: Vec3;
  readonly fovDeg: number;
}

export const DEFAULT_CAMERA_3D: Camera3d = { position: [6, -8, 5], target: [0, 0, 0], fovDeg: 40 };

/** Blinn–Phong light from a direction plus ambient occlusion and a soft shadow, each 0..1 strength. */
export interface Lighting3d {
  /** Direction TOWARDS the light (need not be unit; normalised by the back ends). */
  readonly direction: Vec3;
  readonly ambient: number;
  readonly diffuse: number;
  readonly specular: number;
  /** Phong exponent of the highlight. */
  readonly shininess: number;
  /** Ambient-occlusion strength (0 = off). */
  readonly occlusion: number;
  /** Soft-shadow strength (0 = off). */
  readonly shadow: number;
}

export const DEFAULT_LIGHTING_3D: Lighting3d = {
  direction: [0.4, -0.5, 0.8],
  ambient: 0.25,
  diffuse: 0.8,
  specular: 0.35,
  shininess: 32,
  occlusion: 0.6,
  shadow: 0.5,
};

/** How a hit point is coloured. */
export type Coloring3d =
  /** The seed's own colour, hue-rotated by `step` turns per inversion (colour wheel, Fig. 28 b/e). */
  | { readonly mode: 'depth-wheel'; readonly step: number }
  /** Cosine palette a + b·cos(2π(c·t + d)), t = depth·step. */
  | {
      readonly mode: 'cosine';
      readonly a: Color;
      readonly b: Color;
      readonly c: Color;
      readonly d: Color;
      readonly step: number;
    }
  /** By the hit point's own coordinates (surface coordinates), `scale` world units per colour cycle. */
  | { readonly mode: 'surface'; readonly scale: number }
  /** By the final point of the IIS (Fig. 34), `scale` world units per colour cycle. */
  | { readonly mode: 'final-point'; readonly scale: number }
  /**
   * By a measure m of the hit point p (Fig. 34): `distance` |p| from the origin, `argument`
   * atan2(p_y, p_x)/2π turns about the z axis, `formula` a formula of p's x, y, z and the depth n
   * (docs/formula.md "Colour functions"); t = offset + frequency·m picks the colour: the seed
   * colour's hue turned by t (`wheel`), else the cosine palette a + b·cos(2π(c·t + d)).
   */
  | {
      readonly mode: 'distance' | 'argument' | 'formula';
      /** The `formula` mode's colour function (checked by the render node). */
      readonly formula?: string;
      readonly wheel: boolean;
      readonly a: Color;
      readonly b: Color;
      readonly c: Color;
      readonly d: Color;
      readonly frequency: number;
      readonly offset: number;
    };

/**
 * Volume rendering of the nesting depth (paper §4.2, Fig. 10; docs/math-3d.md "§11 Volume rendering
 * of the nesting depth"): along each ray `steps` samples, each point's IIS depth k (k ≥ depthFrom;
 * shallower points are empty) clamped to k' = min(k, depthTo) gives the extinction
 * σ = density·growth^(k' − depthFrom) per world unit and the cosine palette colour at
 * u = (k' − depthFrom + 1)/(depthTo − depthFrom + 1).
 */
export interface Volume3d {
  /** Samples per ray inside the bounding ball of the element regions (the quality). */
  readonly steps: number;
  /** Extinction per world unit at depth `depthFrom`. */
  readonly density: number;
  /** Factor of the extinction per level deeper (deeper spheres are smaller: they need more). */
  readonly growth: number;
  /** The least depth with any density (≥ 1: depth 0 is the empty fundamental domain). */
  readonly depthFrom: number;
  /** The depth where the palette ends and the extinction stops growing (≥ depthFrom). */
  readonly depthTo: number;
  readonly a: Color;
  readonly b: Color;
  readonly c: Color;
  readonly d: Color;
}

/**
 * What a ray that hits nothing sees, primary or reflected (docs/math-3d.md "Mirror material"):
 * `flat` the background colour; `sky` a gradient from the horizon colour up to the background
 * colour at the zenith, and below the horizon the ground colour.
 */
export type Environment3d =
  | { readonly mode: 'flat' }
  | { readonly mode: 'sky'; readonly horizon: Color; readonly ground: Color };

/** Bounces a reflected ray may take at most (the shader's loop bound; the depth is a uniform). */
export const MAX_REFLECTIONS = 4;
export const DEFAULT_REFLECTIONS = 2;

/** What the 3D view draws for a node (wireframe, in the node's colour). */
export type Overlay3dShape =
  | { readonly shape: 'point'; readonly at: Vec3 }
  | { readonly shape: 'sphere'; readonly sphere: Sphere }
  | { readonly shape: 'plane'; readonly plane: Plane }
  | { readonly shape: 'box'; readonly center: Vec3; readonly halfSize: Vec3 };

export interface Overlay3dItem {
  readonly nodeId: string;
  readonly color: string;
  readonly label?: string;
  readonly shape: Overlay3dShape;
}

/**
 * A draggable point of a node in space. The view moves it in the plane through `at` parallel to
 * the screen and hands the new position to nodes/graph/drag-patches-3d.ts → dragPatches3d
 * (a radius handle is a point on the sphere: the node turns it back into a radius).
 */
export interface Handle3dItem {
  readonly nodeId: string;
  /** Handle id, unique within the node, passed back to the node type's `drag3d`. */
  readonly handle: string;
  readonly at: Vec3;
}

export interface Scene3d {
  readonly kind: '3d';
  /** Tested in this order at every step, like the 2D render's elements. */
  readonly elements: readonly Element3d[];
  /** The orbit seeds whose images are drawn (none: nothing to hit; the node says so). */
  readonly seeds: readonly Seed3d[];
  readonly camera: Camera3d;
  readonly maxIterations: number;
  /** Sphere-tracing steps per ray. */
  readonly marchSteps: number;
  /** The distance estimate is multiplied by this (≤ 1) before each march step (paper §4.2). */
  readonly deScale: number;
  readonly lighting: Lighting3d;
  readonly coloring: Coloring3d;
  readonly background: Color;
  /** What rays that hit nothing see (absent: `flat`, the background colour). */
  readonly environment?: Environment3d;
  /** Reflections a ray may take off mirror seeds, 0…MAX_REFLECTIONS (absent: DEFAULT_REFLECTIONS). */
  readonly reflections?: number;
  /** Progressive anti-aliasing samples per pixel when the view is still. */
  readonly samples: number;
  /** Set: the picture is the volume-rendered nesting depth (Fig. 10) instead of the traced surfaces. */
  readonly volume?: Volume3d;
  /** Id of the render-3d node. */
  readonly renderNodeId: string;
  readonly overlays: readonly Overlay3dItem[];
  readonly handles: readonly Handle3dItem[];
  /** Quaternion Kleinian groups whose limit sets are drawn as dots over the traced picture. */
  readonly limitSets?: readonly LimitSet3d[];
}
