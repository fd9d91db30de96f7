/**
 * Which snap a Shift-drag uses, decided from the construction drawn around the handle (pure):
 * - a handle on the rim of its own node's circle → tangency with the nearest other circle within
 *   OVERLAY_PX.tangentSnap, else the radius rounded to the grid step;
 * - a handle at the end of a drawn line (its own node's, or a line wired from this point) → the
 *   line's direction about its other end to multiples of π/12, or to meet another drawn line at
 *   π/n (n = 2..12: mirrors at π/n tile), whichever is nearer, keeping the length;
 * - anything else → the grid.
 * The result carries a guide the overlay draws so the user sees why the handle jumped.
 */
import type { HandleItem, OverlayItem } from '../../../nodes/core/scene.ts';
import type { Circle, Line, Vec2 } from '../../../nodes/core/values.ts';
import { dist } from '../../../nodes/geometry/vec.ts';
import { ANGLE_SNAP_DIVISIONS, MIRROR_SNAP_MAX_N, OVERLAY_PX } from './constants.ts';
import {
  niceGridStep,
  pointAtRadius,
  snapAngle,
  snapAngleToLine,
  snapRadiusToStep,
  snapRadiusToTangent,
  snapToGrid,
} from './snap.ts';

export type SnapGuide =
  | { readonly kind: 'grid'; readonly step: number }
  | {
      readonly kind: 'angle';
      readonly pivot: Vec2;
      readonly degrees: number;
      /** Set when the snap is to π/n with another line: "π/3", and that line (drawn as a guide). */
      readonly piOver?: { readonly n: number; readonly line: Line };
    }
  | { readonly kind: 'tangent'; readonly center: Vec2; readonly touching: Circle }
  | { readonly kind: 'radius'; readonly center: Vec2; readonly radius: number };

export interface Snapped {
  readonly at: Vec2;
  readonly guide: SnapGuide;
}

/** Same point up to rounding of the evaluation (relative 1e-9). */
const coincide = (a: Vec2, b: Vec2) =>
  dist(a, b) <= 1e-9 * Math.max(1, Math.abs(a[0]), Math.abs(a[1]), Math.abs(b[0]), Math.abs(b[1]));

/** The centre of the circle of the handle's own node whose rim the handle sits on, if any. */
function rimCenter(overlays: readonly OverlayItem[], handle: HandleItem): Vec2 | null {
  for (const item of overlays) {
    if (item.nodeId !== handle.nodeId || item.shape.shape !== 'circle') continue;
    const { c, r } = item.shape.circle;
    if (r > 0 && Math.abs(dist(c, handle.at) - r) <= 1e-9 * Math.max(1, r)) return c;
  }
  return null;
}

/** The other ends of every drawn line that has an end at the handle. */
function linePivots(overlays: readonly OverlayItem[], handle: HandleItem): Vec2[] {
  const pivots: Vec2[] = [];
  for (const item of overlays) {
    if (item.shape.shape !== 'line') continue;
    const { a, b } = item.shape.line;
    if (coincide(a, handle.at) && !coincide(b, handle.at)) pivots.push(b);
    else if (coincide(b, handle.at) && !coincide(a, handle.at)) pivots.push(a);
  }
  return pivots;
}

/** Drawn lines with no end at the handle (those turn with it): what the line may meet at π/n. */
function otherLines(overlays: readonly OverlayItem[], handle: HandleItem): Line[] {
  const lines: Line[] = [];
  for (const item of overlays) {
    if (item.shape.shape !== 'line') continue;
    const { a, b } = item.shape.line;
    if (!coincide(a, handle.at) && !coincide(b, handle.at) && !coincide(a, b)) lines.push(item.shape.line);
  }
  return lines;
}

/** Where a Shift-drag of `handle` toward world point `want` lands, at `pxPerWorld` zoom. */
export function snapHandle(
  overlays: readonly OverlayItem[],
  handle: HandleItem,
  want: Vec2,
  pxPerWorld: number,
): Snapped {
  const step = niceGridStep(pxPerWorld, OVERLAY_PX.gridMinCell);
  const center = rimCenter(overlays, handle);
  if (center) {
    const others = overlays
      .filter((o) => o.nodeId !== handle.nodeId && o.shape.shape === 'circle')
      .map((o) => (o.shape as { circle: Circle }).circle);
    const tangent = snapRadiusToTangent(
      center,
      dist(center, want),
      others,
      OVERLAY_PX.tangentSnap / pxPerWorld,
    );
    if (tangent) {
      return {
        at: pointAtRadius(center, want, tangent.radius),
        guide: { kind: 'tangent', center, touching: others[tangent.index] },
      };
    }
    const at = snapRadiusToStep(center, want, step);
    return { at, guide: { kind: 'radius', center, radius: dist(center, at) } };
  }
  let best: Snapped | null = null;
  const degreesOf = (at: Vec2, pivot: Vec2) =>
    Math.round((Math.atan2(at[1] - pivot[1], at[0] - pivot[0]) * 180) / Math.PI);
  const others = otherLines(overlays, handle);
  for (const pivot of linePivots(overlays, handle)) {
    const at = snapAngle(want, pivot, ANGLE_SNAP_DIVISIONS);
    if (!best || dist(at, want) < dist(best.at, want))
      best = { at, guide: { kind: 'angle', pivot, degrees: degreesOf(at, pivot) } };
    for (const line of others) {
      const ref = Math.atan2(line.b[1] - line.a[1], line.b[0] - line.a[0]);
      const snapped = snapAngleToLine(want, pivot, ref, MIRROR_SNAP_MAX_N);
      // Strictly nearer only: an exact tie keeps the plain 15° step (π/4 with a horizontal line).
      if (dist(snapped.at, want) < dist(best.at, want) - 1e-12)
        best = {
          at: snapped.at,
          guide: {
            kind: 'angle',
            pivot,
            degrees: degreesOf(snapped.at, pivot),
            piOver: { n: snapped.n, line },
          },
        };
    }
  }
  return best ?? { at: snapToGrid(want, step), guide: { kind: 'grid', step } };
}
