/**
 * The plain values of the plane (points, lines, circles, colours, pictures): JSON-compatible data
 * that documents, the evaluator, the Scene and the UI share. Imports nothing, so every layer can
 * use it; what each port type carries (these plus scene elements) is PortValueMap in port-values.ts.
 */

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
  /**
   * A live source (camera, video) the browser draws in place of the picture, cropped to its
   * width:height; `src` is then the fallback drawn wherever the source is not running (the CLI,
   * a denied camera). See nodes/core/live-source.ts.
   */
  readonly live?: LiveRef;
}

/** Which live source an image node asked for (the stream itself never enters the document). */
export interface LiveRef {
  readonly kind: 'webcam' | 'video';
  /** The image node that asked for it (its messages go there; a video is per node). */
  readonly nodeId: string;
  /** The video file's name (a label only); '' for the camera. */
  readonly label: string;
  /** A small video kept inline in the document (data:video/… URL), else ''. */
  readonly src: string;
}

/**
 * The picture shown when no picture is chosen: drawn procedurally (shader-gen/picture.ts) from
 * this src, a checker with an arrow pointing up so the orientation of every copy shows.
 */
export const BUILTIN_PICTURE: ImageRef = { src: 'builtin:checker-arrow', width: 256, height: 256 };
