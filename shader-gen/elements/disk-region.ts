/** Membership in a DiskRegion: |p−c| < r, or |p−c| > r when `outside` (both strict). */
import type { DiskRegion } from '../../nodes/core/scene.ts';

export function inRegion(region: DiskRegion, x: number, y: number): boolean {
  const dx = x - region.c[0];
  const dy = y - region.c[1];
  const d2 = dx * dx + dy * dy;
  const r2 = region.r * region.r;
  return region.outside ? d2 > r2 : d2 < r2;
}

export const regionBoundaryDistance = (region: DiskRegion, x: number, y: number): number =>
  Math.abs(Math.hypot(x - region.c[0], y - region.c[1]) - region.r);
