/**
 * The sub-pixel sample pattern shared by the CPU raster and the GPU's progressive accumulation.
 * (The pixel ↔ world mapping lives with the view, in nodes/core/view.ts.)
 */
import type { Vec2 } from '../nodes/core/values.ts';

/** R2 low-discrepancy sequence (plastic constant): g = 1.32471795724…, α = (1/g, 1/g²). */
const R2 = [0.7548776662466927, 0.5698402909980532] as const;

/** Offset of sample k inside a pixel: k = 0 is the centre; k > 0 follows the R2 sequence. */
export function sampleOffset(k: number): Vec2 {
  if (k === 0) return [0.5, 0.5];
  return [(0.5 + k * R2[0]) % 1, (0.5 + k * R2[1]) % 1];
}
