/**
 * A quaternion Kleinian group as the Render 3D node receives it (port type `limit3`): its generators
 * as Sp^K(1,1) matrices and how its limit set is searched and drawn (docs/math-3d.md "Quaternion
 * Kleinian groups"). The search itself runs in shader-gen/space/limit-dfs-3d.ts, at the camera.
 */
import type { QMatrix } from '../geometry/space/quaternion-mobius.ts';
import type { Color } from './values.ts';

export interface LimitSet3d {
  readonly nodeId: string;
  /** Two generators, pseudo-determinant 1 (their inverses are added by the search). */
  readonly generators: readonly [QMatrix, QMatrix];
  /** A branch ends when its points are this many pixels apart or closer. */
  readonly leafPx: number;
  /** Dot radius in pixels at the camera's target distance (nearer dots are bigger). */
  readonly dotPx: number;
  /** The longest word. */
  readonly maxDepth: number;
  /** The most words one search visits. */
  readonly maxWords: number;
  /** Dot colours by the word's first letter: a, b, A, B. */
  readonly colors: readonly [Color, Color, Color, Color];
}
