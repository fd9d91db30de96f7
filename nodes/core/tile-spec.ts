/**
 * How the IIS result is coloured: the tile's colouring modes, orbit seeds and the TileSpec the
 * tile node hands to the render node (shader-gen/colour.ts implements it on CPU and GPU).
 */
import type { Circle, Color, ImageRef, Vec2 } from './values.ts';

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
   * A true kaleidoscope of a picture: the picture's texel at the final point (docs/math.md "by final
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
  | { readonly mode: 'limit-set'; readonly glow: number }
  /**
   * A cosine palette a + b·cos(2π(c·t + d)) of t = offset + scale·m, where m is a measure of the
   * run rather than its depth (docs/math.md "Colouring by a measure"): the final point's x, y,
   * radius or argument (in turns), its distance to the nearest tile edge (in the tile's own
   * coordinates), the escape speed ln s, or an orbit trap (the orbit's least distance to `trap`).
   */
  | {
      readonly mode: 'measure';
      readonly measure: Measure;
      readonly a: Color;
      readonly b: Color;
      readonly c: Color;
      readonly d: Color;
      readonly scale: number;
      readonly offset: number;
      /** The orbit trap: a circle (radius 0: a point); read by the `trap` measure only. */
      readonly trap: Circle;
      /**
       * The `formula` measure's formula of the final point z = (x, y), the depth n and the scale s
       * (docs/formula.md "Colour functions"); checked by the tile node, so it always checks here.
       */
      readonly formula?: string;
    };

/** What a measure colouring measures (docs/math.md "Colouring by a measure"). */
export const MEASURES = ['x', 'y', 'radius', 'argument', 'edge', 'speed', 'trap', 'formula'] as const;
export type Measure = (typeof MEASURES)[number];

/**
 * An orbit seed (docs/math.md "orbit seeds", the paper's Figs. 2 and 11): tested at the start of every
 * step, so every image of the seed under the group is painted. A disk paints its colour; an image
 * rectangle (centre, width × height world units, turned by `rotation` radians) paints its picture; a
 * shape paints its colour where its formula is negative.
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
    }
  | {
      /** The region where a formula of z = (x, y) is negative (docs/formula.md "Seed shapes"). */
      readonly kind: 'shape';
      readonly nodeId: string;
      readonly formula: string;
      /** The formula's numbers a, b, c and the time t, and its points p = (x, y), q = (z, w). */
      readonly numbers: readonly [number, number, number, number];
      readonly points: readonly [number, number, number, number];
      readonly color: Color;
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

/** The cosine palette, the colouring a tile has by default. */
export type CosineColoring = Extract<Coloring, { mode: 'cosine' }>;

/** The default colouring ("rainbow"), also the cosine-palette node's preset of that name. */
export const DEFAULT_COLORING: CosineColoring = {
  mode: 'cosine',
  a: [0.5, 0.5, 0.5],
  b: [0.5, 0.5, 0.5],
  c: [1, 1, 1],
  d: [0, 0.33, 0.67],
  step: 0.07,
};

/**
 * The tile used when a render node has no tile wired (and for an empty scene). The tile node's
 * defaults are these values, so there is one home for them.
 */
export const DEFAULT_TILE: TileSpec = {
  nodeId: '',
  coloring: DEFAULT_COLORING,
  limitColor: [0.02, 0.02, 0.03],
  background: [0.06, 0.06, 0.08],
  edgeWidth: 0,
  edgeColor: [1, 1, 1],
};
