/**
 * The Scene: the small resolved form between the graph and both back ends (CPU interpreter and
 * GLSL compiler). Every construction is already done; only element data with numbers remains.
 * Its parts have their own modules (elements, tile, overlay, view, limits); they are re-exported
 * here because the back ends and the app read them as one vocabulary.
 */
import type { SceneFigures } from './figures.ts';
import { LIMITS } from './limits.ts';
import type { HandleItem, OverlayItem } from './overlay.ts';
import type { SceneElement } from './scene-elements.ts';
import type { TileSpec } from './tile-spec.ts';
import type { Circle } from './values.ts';
import type { View } from './view.ts';

export { NO_FIGURES, type SceneFigures } from './figures.ts';
export { LIMITS } from './limits.ts';
export type { HandleItem, OverlayItem, OverlayShape } from './overlay.ts';
export type * from './scene-elements.ts';
export {
  type Coloring,
  type CosineColoring,
  DEFAULT_COLORING,
  DEFAULT_TILE,
  MEASURES,
  type Measure,
  type SeedKind,
  type SeedSpec,
  type TileSpec,
} from './tile-spec.ts';
export type { View } from './view.ts';

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
  /** Pictures of the group drawn over the render (absent: none). */
  readonly figures?: SceneFigures;
}

export const EMPTY_SCENE_DEFAULTS = { maxIterations: LIMITS.defaultMaxIterations, samples: 4 } as const;
