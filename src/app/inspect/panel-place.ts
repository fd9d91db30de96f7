/**
 * Where the "Explain this pixel" panel goes in the render pane (CSS px, pure): beside the clicked
 * point when the pane is wide enough for a readable panel on the point's far side, otherwise above
 * or below it, whichever has more room. Either way the point itself stays uncovered, so the panel
 * never hides the pixel it explains (a narrow pane used to get a side panel as wide as itself).
 */
import type { Vec2 } from '../../../nodes/core/values.ts';

export interface PanelPlace {
  readonly left?: number;
  readonly right?: number;
  readonly top: number;
  readonly width?: number;
  readonly maxHeight: number;
}

/** The panel's preferred and least readable widths. */
const WIDE = 390;
const NARROWEST = 240;
/** Room kept around the point, from the pane's edges, and under the pane's own buttons at the top. */
const GAP = 16;
const EDGE = 12;
const TOP = 44;

export function panelPlace(point: Vec2 | null, width: number, height: number): PanelPlace {
  const full = Math.max(0, height - TOP - EDGE);
  if (!point) return { right: EDGE, top: TOP, width: Math.min(WIDE, width - 2 * EDGE), maxHeight: full };
  const [x, y] = point;
  const leftRoom = x - GAP - EDGE;
  const rightRoom = width - x - GAP - EDGE;
  if (Math.max(leftRoom, rightRoom) >= NARROWEST) {
    return rightRoom >= leftRoom
      ? { right: EDGE, top: TOP, width: Math.min(WIDE, rightRoom), maxHeight: full }
      : { left: EDGE, top: TOP, width: Math.min(WIDE, leftRoom), maxHeight: full };
  }
  const above = y - GAP - TOP;
  const below = height - y - GAP - EDGE;
  return below >= above
    ? { left: EDGE, right: EDGE, top: y + GAP, maxHeight: Math.max(0, below) }
    : { left: EDGE, right: EDGE, top: TOP, maxHeight: Math.max(0, above) };
}
