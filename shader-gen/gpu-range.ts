/**
 * Scene numbers the GPU cannot compute with. The evaluator accepts any finite float64, but the
 * shader works in float32 and squares coordinates and radii, so a value beyond
 * LIMITS.gpuMaxMagnitude becomes ∞ on the GPU while the CPU interpreter (float64) still draws it.
 */
import { firstBeyond } from '../nodes/core/limits.ts';
import { LIMITS, type Scene } from '../nodes/core/scene.ts';
import { elementRecord } from './elements/index.ts';

export interface OutOfRange {
  /** The node whose element (or the render node, for the clip disk) holds the value. */
  readonly nodeId: string | undefined;
  readonly value: number;
}

/**
 * The first scene value beyond LIMITS.gpuMaxMagnitude that becomes a uniform: elements, then the
 * tile's seeds, picture placement and inner circle, then the clip disk. Picture data (`src`) holds no
 * numbers that reach the shader, so only the geometric fields are checked.
 */
export function firstOutOfGpuRange(scene: Scene, max: number = LIMITS.gpuMaxMagnitude): OutOfRange | null {
  for (const e of scene.elements) {
    // The element's fields and what it packs for the shader (which may square them: an
    // inversion packs r², so r = 10¹⁰ is within range but its packed r² = 10²⁰ is not). The
    // fields first, so the message names the number the user typed when that is the culprit.
    const value = firstBeyond(e, max) ?? firstBeyond(elementRecord(e).glsl.pack(e), max);
    if (value !== undefined) return { nodeId: e.nodeId, value };
  }
  const { tile } = scene;
  for (const seed of tile.seeds ?? []) {
    const value =
      seed.kind === 'disk'
        ? firstBeyond([seed.c, seed.r], max)
        : seed.kind === 'shape'
          ? firstBeyond([seed.numbers, seed.points], max)
          : firstBeyond([seed.center, seed.width, seed.height, seed.rotation], max);
    if (value !== undefined) return { nodeId: seed.nodeId, value };
  }
  const coloring = tile.coloring;
  const placement =
    coloring.mode === 'image'
      ? [coloring.center, coloring.size, coloring.rotation]
      : coloring.mode === 'measure'
        ? [coloring.trap.c, coloring.trap.r, coloring.scale, coloring.offset]
        : [];
  const tileValue = firstBeyond([placement, tile.inner ?? null], max);
  if (tileValue !== undefined) return { nodeId: tile.nodeId || undefined, value: tileValue };
  const clip = firstBeyond(scene.clip, max);
  if (clip !== undefined) return { nodeId: scene.renderNodeId ?? undefined, value: clip };
  return null;
}
