/**
 * The orbit of an inspected point placed on screen ("Explain this pixel"): the start and at most
 * MAX_DRAWN_STEPS steps as CSS points, the segments between successive points clipped to the pane
 * (a step far outside the view — near an inversion centre it may land ~10¹⁸ away — still draws
 * the part of its segment that crosses the view), and numbered markers only where they show.
 */
import type { Vec2 } from '../../../nodes/core/values.ts';
import { clipSegmentToRect, type Screen, toCss } from './screen.ts';

/** Steps drawn at most; the panel says when more were taken. */
export const MAX_DRAWN_STEPS = 200;
/** Segments are clipped to the pane grown by this many CSS pixels (their ends never show). */
const SEGMENT_MARGIN = 24;

export interface OrbitStep {
  readonly at: Vec2;
  readonly color: string;
}

export interface PlacedOrbit {
  readonly start: Vec2;
  /** Markers inside the pane: step number (1-based) and CSS position. */
  readonly markers: readonly { readonly step: number; readonly at: Vec2; readonly color: string }[];
  /** Clipped segments, each coloured by the step that ends it. */
  readonly segments: readonly { readonly a: Vec2; readonly b: Vec2; readonly color: string }[];
  /** Steps left out (beyond MAX_DRAWN_STEPS). */
  readonly omitted: number;
}

const inside = (p: Vec2, s: Screen) => p[0] >= 0 && p[0] <= s.width && p[1] >= 0 && p[1] <= s.height;

export function placeOrbit(start: Vec2, steps: readonly OrbitStep[], s: Screen): PlacedOrbit {
  const drawn = steps.slice(0, MAX_DRAWN_STEPS);
  const markers: PlacedOrbit['markers'][number][] = [];
  const segments: PlacedOrbit['segments'][number][] = [];
  let prev = toCss(s, start);
  drawn.forEach((step, i) => {
    const at = toCss(s, step.at);
    const finite = Number.isFinite(at[0]) && Number.isFinite(at[1]);
    if (finite) {
      const seg = clipSegmentToRect(prev, at, s.width, s.height, SEGMENT_MARGIN);
      if (seg) segments.push({ a: seg[0], b: seg[1], color: step.color });
      if (inside(at, s)) markers.push({ step: i + 1, at, color: step.color });
      prev = at;
    }
  });
  return { start: toCss(s, start), markers, segments, omitted: steps.length - drawn.length };
}
