/**
 * Membership in a DiskRegion: |p−c| < r, or |p−c| > r when `outside` (both strict), on the CPU and
 * in GLSL. A DiskRegion packs into one vec4: (c.x, c.y, r, outside ? 1 : 0).
 */
import type { DiskRegion } from '../../nodes/core/scene.ts';
import { glslFunction } from '../glsl/snippet.ts';

export function inRegion(region: DiskRegion, x: number, y: number): boolean {
  const dx = x - region.c[0];
  const dy = y - region.c[1];
  const d2 = dx * dx + dy * dy;
  const r2 = region.r * region.r;
  return region.outside ? d2 > r2 : d2 < r2;
}

export const regionBoundaryDistance = (region: DiskRegion, x: number, y: number): number =>
  Math.abs(Math.hypot(x - region.c[0], y - region.c[1]) - region.r);

export const packRegion = (g: DiskRegion): number[] => [g.c[0], g.c[1], g.r, g.outside ? 1 : 0];

/** |p−c| < r, or |p−c| > r when outside (both strict), as inRegion. */
export const inRegionGlsl = glslFunction(
  'inRegion',
  `
bool inRegion(vec4 g, vec2 p) {
  float dx = p.x - g.x;
  float dy = p.y - g.y;
  float d2 = dx * dx + dy * dy;
  float r2 = g.z * g.z;
  return g.w > 0.5 ? d2 > r2 : d2 < r2;
}`,
);

/** ||p−c| − r|, as regionBoundaryDistance. */
export const regionBoundaryDistanceGlsl = glslFunction(
  'regionBoundaryDistance',
  `
float regionBoundaryDistance(vec4 g, vec2 p) {
  return abs(length(p - g.xy) - g.z);
}`,
);
