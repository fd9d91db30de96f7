/**
 * The render node's figure options: pictures of the group drawn over the render (the overlay, SVG
 * and PNG export) from a float64 enumeration on the CPU (shader-gen/figures, docs/math.md "Cayley
 * graph and depth-first limit set").
 */
import type { Vec2 } from './values.ts';

export interface SceneFigures {
  /** Cayley graph: steps from the fundamental tile (0: not drawn). */
  readonly cayleyDepth: number;
  /** The Cayley graph's base point (the fundamental tile's centre); null: chosen automatically. */
  readonly cayleyBase: Vec2 | null;
  /** Draw the limit set by depth-first search of the reduced words (Schottky-type groups). */
  readonly limitSetDfs: boolean;
}

export const NO_FIGURES: SceneFigures = { cayleyDepth: 0, cayleyBase: null, limitSetDfs: false };
