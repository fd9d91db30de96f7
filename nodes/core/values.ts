/**
 * The runtime values that travel along edges. They are plain data (JSON-compatible apart from
 * `element`, which carries scene elements), so documents, the evaluator and the UI share them.
 */
import type { SceneElement, SeedSpec, TileSpec } from './scene.ts';

/** A point or vector of the world plane (y up). */
export type Vec2 = readonly [number, number];

/** A directed line through a and b; the IIS keeps its LEFT side (normal n = (−d_y, d_x)). */
export interface Line {
  readonly a: Vec2;
  readonly b: Vec2;
}

/** A circle with centre c and radius r > 0. */
export interface Circle {
  readonly c: Vec2;
  readonly r: number;
}

/** An sRGB colour with components in [0, 1] (converted to linear light before blending). */
export type Color = readonly [number, number, number];

/** A raster image handed to the tile (image kaleidoscope). `src` is a data: URL or path. */
export interface ImageRef {
  readonly src: string;
  readonly width: number;
  readonly height: number;
}

/** What a port of each type carries at evaluation time. */
export interface PortValueMap {
  number: number;
  point: Vec2;
  line: Line;
  circle: Circle;
  element: readonly SceneElement[];
  tile: TileSpec;
  color: Color;
  image: ImageRef;
  seed: SeedSpec;
}

/**
 * The picture shown when no picture is chosen: drawn procedurally (shader-gen/picture.ts) from
 * this src, a checker with an arrow pointing up so the orientation of every copy shows.
 */
export const BUILTIN_PICTURE: ImageRef = { src: 'builtin:checker-arrow', width: 256, height: 256 };
