/**
 * Moving a render handle from the keyboard: arrow keys on a focused handle move it by a small step
 * on screen, Shift by a big one; each press is one undo step (like one drag). Steps are in screen
 * pixels, so a press moves the point as far as it looks at any zoom.
 */
import type { KeyboardEvent } from 'react';
import type { HandleItem } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { dragPatches, type NodePatch } from '../../../nodes/graph/drag-patches.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { type Screen, toWorld } from './screen.ts';

/** CSS pixels per arrow press: fine enough to place by eye, and five times that with Shift. */
export const HANDLE_STEP_PX = 8;
export const HANDLE_BIG_STEP_PX = 40;

const DIRECTIONS: Record<string, Vec2> = {
  ArrowLeft: [-1, 0],
  ArrowRight: [1, 0],
  ArrowUp: [0, -1],
  ArrowDown: [0, 1],
};

/** The screen offset (CSS px) an arrow key asks for, or null for any other key. */
export function arrowStep(key: string, shift: boolean): Vec2 | null {
  const d = DIRECTIONS[key];
  if (!d) return null;
  const step = shift ? HANDLE_BIG_STEP_PX : HANDLE_STEP_PX;
  return [d[0] * step, d[1] * step];
}

/**
 * The params patches that move `item` (drawn at `css`) by the arrow key of `e`, or null when the
 * key is not an arrow. The handle's own world position is kept exact; only the offset is mapped.
 */
export function handleKeyPatches(
  e: Pick<KeyboardEvent, 'key' | 'shiftKey'>,
  item: HandleItem,
  css: Vec2,
  screen: Screen,
  evaluation: Evaluation,
): NodePatch[] | null {
  const d = arrowStep(e.key, e.shiftKey);
  if (!d) return null;
  const from = toWorld(screen, css);
  const to = toWorld(screen, [css[0] + d[0], css[1] + d[1]]);
  return dragPatches(evaluation, item, [item.at[0] + to[0] - from[0], item.at[1] + to[1] - from[1]]);
}
