/**
 * Shared arithmetic of the strip kinds (translation, parallel mirrors, glide reflection): the
 * signed height h = (p − q)·n across the strip and the strip index k = ⌊h/D⌋ (k = 0 is the
 * half-open tile 0 ≤ h < D, docs/math.md "Closed-form elements").
 */
import type { StripData } from '../../nodes/core/scene.ts';

/** h = (p − q)·n: the height of (x, y) above the strip's first edge. */
export const stripHeight = (e: StripData, x: number, y: number): number =>
  (x - e.q[0]) * e.n[0] + (y - e.q[1]) * e.n[1];

/** k = ⌊h/D⌋: how many periods (x, y) lies away from the tile (negative below it). */
export const stripIndex = (e: StripData, x: number, y: number): number =>
  Math.floor(stripHeight(e, x, y) / e.period);

/** Distance to the nearer strip edge h = 0 or h = D. */
export function stripBoundaryDistance(e: StripData, x: number, y: number): number {
  const h = stripHeight(e, x, y);
  return Math.min(Math.abs(h), Math.abs(h - e.period));
}
