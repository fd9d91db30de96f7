/**
 * The Scene: the small resolved form between the graph and both back ends (CPU interpreter and
 * GLSL compiler). Every construction is already done; only element data with numbers remains.
 * Element kinds are implemented (CPU + GLSL, side by side) in shader-gen/elements/.
 */
import type { Circle, Color, ImageRef, Line, Vec2 } from './values.ts';

/** A disk (|p−c| < r) or, when `outside`, the open complement of the closed disk (|p−c| > r). */
export interface DiskRegion {
  readonly c: Vec2;
  readonly r: number;
  readonly outside: boolean;
}

interface ElementBase {
  /** The node that produced the element: errors and `#line` markers point back to it. */
  readonly nodeId: string;
}

/** Inversion in the circle (c, r): inside |p−c| < r, σ(p) = c + r²(p−c)/|p−c|². */
export interface InversionElement extends ElementBase {
  readonly kind: 'inversion';
  readonly c: Vec2;
  readonly r: number;
}

/**
 * The circle mirror that keeps its inside (an `inversion` node with `flip`): inversion in (c, r)
 * applied OUTSIDE the circle, inside |p−c| > r, σ as for InversionElement.
 */
export interface OuterInversionElement extends ElementBase {
  readonly kind: 'outer-inversion';
  readonly c: Vec2;
  readonly r: number;
}

/** Reflection in the line through q with unit normal n: inside (p−q)·n < 0. */
export interface ReflectionElement extends ElementBase {
  readonly kind: 'reflection';
  readonly q: Vec2;
  readonly n: Vec2;
}

/**
 * Two-circle Möbius generator g = σ_C2∘σ_C1 (math.md). In A apply g, else in B apply
 * g⁻¹ = σ_C1∘σ_C2; A is always tested first. A is bounded by C1, B by C1' = σ_C2(C1).
 */
export interface MobiusElement extends ElementBase {
  readonly kind: 'mobius';
  readonly c1: Circle;
  readonly c2: Circle;
  readonly a: DiskRegion;
  readonly b: DiskRegion;
}

/**
 * Loxodromic generator from two nested circles and a control point (math.md): inside A (C1)
 * p ← σ_C2(σ_C1(σ_C3(ρ_L(p)))); inside B (outside C1') p ← ρ_L(σ_C3(σ_C1(σ_C2(p)))).
 */
export interface LoxodromicElement extends ElementBase {
  readonly kind: 'loxodromic';
  readonly c1: Circle;
  readonly c2: Circle;
  readonly c3: Circle;
  /** ρ_L: reflection in the line through c1 and c2 (q, unit normal n). */
  readonly lq: Vec2;
  readonly ln: Vec2;
  readonly a: DiskRegion;
  readonly b: DiskRegion;
}

/**
 * Möbius map from a det-1 matrix (math.md "Möbius from a matrix"), complex entries as [re, im]:
 * inside I(g) (`forward`, centre −d/c) apply g(z) = (az + b)/(cz + d); else inside I(g⁻¹)
 * (`backward`, centre a/c) apply g⁻¹(z) = (dz − b)/(−cz + a). Both radii are 1/|c|.
 */
export interface MobiusMatrixElement extends ElementBase {
  readonly kind: 'mobius-matrix';
  readonly a: Vec2;
  readonly b: Vec2;
  readonly c: Vec2;
  readonly d: Vec2;
  readonly forward: DiskRegion;
  readonly backward: DiskRegion;
}

/** A strip across the unit direction n: h = (p−q)·n, tile 0 ≤ h < period (closed-form kinds). */
export interface StripData {
  readonly q: Vec2;
  readonly n: Vec2;
  readonly period: number;
}

/**
 * Translation by `shift` (default period·n), folded in closed form: p ← p − ⌊h/D⌋·shift. An
 * oblique shift (shift·n = period, not along n) lets two strips make any lattice: each strip's
 * normal is perpendicular to the other's shift, so neither fold changes the other's h.
 */
export interface TranslationElement extends ElementBase, StripData {
  readonly kind: 'translation';
  readonly shift?: Vec2;
}

/** The reflections in the parallel lines h = 0 and h = period, folded in closed form. */
export interface ParallelMirrorsElement extends ElementBase, StripData {
  readonly kind: 'parallel-mirrors';
}

/** Glide: translate by period·n and reflect in the axis through q along n, in closed form. */
export interface GlideReflectionElement extends ElementBase, StripData {
  readonly kind: 'glide-reflection';
}

/** Rotation by 2π/order about c; tile = the wedge from unit direction b1 counter-clockwise. */
export interface RotationElement extends ElementBase {
  readonly kind: 'rotation';
  readonly c: Vec2;
  readonly b1: Vec2;
  readonly order: number;
}

/**
 * Spiral similarity g(p) = c + (r2/r1)² R_2φ (p − c) (φ = `angle`, radians; 0 < r1 < r2); tile =
 * the annulus r1 ≤ |p − c| < r2²/r1, folded in closed form.
 */
export interface SpiralSimilarityElement extends ElementBase {
  readonly kind: 'spiral-similarity';
  readonly c: Vec2;
  readonly r1: number;
  readonly r2: number;
  readonly angle: number;
}

export type SceneElement =
  | InversionElement
  | OuterInversionElement
  | ReflectionElement
  | MobiusElement
  | LoxodromicElement
  | MobiusMatrixElement
  | TranslationElement
  | ParallelMirrorsElement
  | GlideReflectionElement
  | RotationElement
  | SpiralSimilarityElement;
export type ElementKind = SceneElement['kind'];

/** How a point is coloured from its IIS result. */
export type Coloring =
  /** HSV with hue = hueOffset + hueStep·depth (hue in turns). */
  | {
      readonly mode: 'depth-hsv';
      readonly hueOffset: number;
      readonly hueStep: number;
      readonly saturation: number;
      readonly value: number;
    }
  /** Cosine palette a + b·cos(2π(c·t + d)), t = depth·step (Quilez). */
  | {
      readonly mode: 'cosine';
      readonly a: Color;
      readonly b: Color;
      readonly c: Color;
      readonly d: Color;
      readonly step: number;
    }
  /** Two tones by the parity of depth. */
  | { readonly mode: 'parity'; readonly even: Color; readonly odd: Color }
  /**
   * A true kaleidoscope of a picture: the picture's texel at the final point (math.md "by final
   * position"). The picture is `size` world units high, centred at `center`, turned by `rotation`
   * radians counter-clockwise, and repeats beyond its edges.
   */
  | {
      readonly mode: 'image';
      readonly image: ImageRef;
      readonly center: Vec2;
      readonly size: number;
      readonly rotation: number;
    }
  /**
   * Only the limit set: points still moving at maxIterations in the limit colour, escaped ones in
   * the background, except within about a pixel of the limit set (distance estimate: (tile-edge
   * distance + smallest inside radius) / s) and, when glow > 0, a glow exp(−L/glow) around it
   * (L that distance in pixels, glow in pixels).
   */
  | { readonly mode: 'limit-set'; readonly glow: number };

/**
 * An orbit seed (math.md "orbit seeds", the paper's Figs. 2 and 11): tested at the start of every
 * step, so every image of the seed under the group is painted. A disk paints its colour; an image
 * rectangle (centre, width × height world units, turned by `rotation` radians) paints its picture.
 */
export type SeedSpec =
  | {
      readonly kind: 'disk';
      readonly nodeId: string;
      readonly c: Vec2;
      readonly r: number;
      readonly color: Color;
    }
  | {
      readonly kind: 'image';
      readonly nodeId: string;
      readonly center: Vec2;
      readonly width: number;
      readonly height: number;
      readonly rotation: number;
      readonly image: ImageRef;
    };
export type SeedKind = SeedSpec['kind'];

export interface TileSpec {
  readonly nodeId: string;
  readonly coloring: Coloring;
  /** Colour of points still moving at maxIterations (on or near the limit set). */
  readonly limitColor: Color;
  /** Colour outside the clip disk (e.g. outside the Poincaré disk). */
  readonly background: Color;
  /** Tile edges drawn this many pixels wide using the accumulated scale (0 = none). */
  readonly edgeWidth: number;
  readonly edgeColor: Color;
  /** Colour of depth 0, the fundamental tile itself (absent/null: coloured like any depth). */
  readonly fill?: Color | null;
  /** Orbit seeds, tested in order at the start of every step (absent: none). */
  readonly seeds?: readonly SeedSpec[];
  /** Points that hit no seed get the background: only the seeds' orbits show (Fig. 2). */
  readonly seedsOnly?: boolean;
  /**
   * Depth shading of the seeds' images: a seed met after `depth` steps paints its colour times
   * max(0, 1 − seedFade·depth) (absent/0: no shading).
   */
  readonly seedFade?: number;
  /**
   * Internal area (the paper's Fig. 22): escaped points keep their colour only when their final
   * point lies inside this circle; the others get the background (absent/null: no test).
   */
  readonly inner?: Circle | null;
}

/** A view: `center` is the world point at the middle of the canvas, `scale` the world height. */
export interface View {
  readonly center: Vec2;
  readonly scale: number;
}

/** What the overlay draws for a node (in the node's colour), with its draggable handles. */
export type OverlayShape =
  | { readonly shape: 'point'; readonly at: Vec2 }
  | { readonly shape: 'line'; readonly line: Line }
  | { readonly shape: 'circle'; readonly circle: Circle };

export interface OverlayItem {
  readonly nodeId: string;
  readonly color: string;
  readonly label?: string;
  readonly shape: OverlayShape;
}

export interface HandleItem {
  readonly nodeId: string;
  /** Handle id, unique within the node, passed back to the node type's `drag`. */
  readonly handle: string;
  readonly at: Vec2;
}

export interface Scene {
  readonly elements: readonly SceneElement[];
  readonly tile: TileSpec;
  readonly maxIterations: number;
  readonly samples: number;
  /** Points outside this disk get the background colour (null: no clipping). */
  readonly clip: Circle | null;
  readonly view: View;
  readonly overlays: readonly OverlayItem[];
  readonly handles: readonly HandleItem[];
  /** Id of the render node, or null when the graph has none (then the scene is empty). */
  readonly renderNodeId: string | null;
}

/** Bounds shared by the validator, evaluator and compiler (one home for each limit). */
export const LIMITS = {
  maxElements: 256,
  maxIterations: 10_000,
  maxSamples: 256,
  maxNodes: 5_000,
  /**
   * Deepest nesting of objects and arrays a document may have (the document itself is level 0).
   * Real documents need about 8; JSON.stringify and structuredClone overflow at a few thousand.
   */
  maxJsonDepth: 64,
  defaultMaxIterations: 100,
  /**
   * vec4 uniform rows a generated fragment shader may declare: WebGL2 guarantees 224
   * (MAX_FRAGMENT_UNIFORM_VECTORS); 16 stay free for what ANGLE and drivers add internally.
   */
  maxUniformVectors: 208,
  /**
   * Largest magnitude of a scene number the GPU computes with safely: the shader squares
   * coordinates and radii in float32 (max ≈ 3.4e38), so |v| must stay below √3.4e38 ≈ 1.8e19.
   */
  gpuMaxMagnitude: 1e19,
  /** Largest width or height of an exported image (CLI render, PNG export), in pixels. */
  maxImageSide: 16_384,
  /** Share links: the longest `#g=` fragment accepted (characters of base64url). */
  shareFragmentMaxChars: 512 * 1024,
  /** Share links: the most bytes a fragment may inflate to (stops a zip bomb early). */
  shareInflatedMaxBytes: 4 * 1024 * 1024,
  /** Longest picture data: URL an image node keeps (the document carries it inline). */
  maxImageDataUrlChars: 4 * 1024 * 1024,
  /** Largest width or height of a picture used as a texture (every WebGL2 GPU has 4096). */
  maxPictureSide: 4096,
  /** Orbit seeds a tile may have (each one is tested at every step of every sample). */
  maxSeeds: 16,
} as const;

/**
 * The tile used when a render node has no tile wired (and for an empty scene). The tile node's
 * defaults are these values, so there is one home for them.
 */
export const DEFAULT_TILE: TileSpec = {
  nodeId: '',
  coloring: {
    mode: 'cosine',
    a: [0.5, 0.5, 0.5],
    b: [0.5, 0.5, 0.5],
    c: [1, 1, 1],
    d: [0, 0.33, 0.67],
    step: 0.07,
  },
  limitColor: [0.02, 0.02, 0.03],
  background: [0.06, 0.06, 0.08],
  edgeWidth: 0,
  edgeColor: [1, 1, 1],
};

export const EMPTY_SCENE_DEFAULTS = { maxIterations: LIMITS.defaultMaxIterations, samples: 4 } as const;
