/**
 * Moving a 3D handle from the keyboard, as the 2D handles move (overlay/handle-keys.ts): arrow keys
 * move the focused handle across the screen by the same pixel steps (in the plane through it
 * parallel to the screen, as a drag does), and Page Up / Page Down move it away from / toward the
 * camera by a tenth of its distance (Shift: five times the step), the one direction a drag cannot
 * give. Each press is one undo step.
 */
import type { KeyboardEvent } from 'react';
import type { Camera3d, Handle3dItem } from '../../../nodes/core/scene-3d.ts';
import { add3, len3, scale3, sub3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import type { NodePatch } from '../../../nodes/graph/drag-patches.ts';
import { dragPatches3d } from '../../../nodes/graph/drag-patches-3d.ts';
import type { Evaluation } from '../../../nodes/graph/evaluate.ts';
import { type PaneSize, pointOnScreenPlane } from '../camera-3d.ts';
import { arrowStep } from '../overlay/handle-keys.ts';

/** Page Up / Page Down move a handle by this fraction of its distance from the camera. */
export const DEPTH_STEP = 0.1;
const DEPTH_BIG_STEP = 0.5;

/**
 * Where a handle at `at`, drawn at pane pixel (x, y), goes for the key of `e`; null for a key that
 * does not move handles (or a move the camera cannot show, e.g. behind it).
 * Depth: p' = p + s·(p − eye), s = ±DEPTH_STEP, so the handle stays on its line of sight.
 */
export function handleKeyTarget3d(
  e: Pick<KeyboardEvent, 'key' | 'shiftKey'>,
  at: Vec3,
  x: number,
  y: number,
  camera: Camera3d,
  pane: PaneSize,
): Vec3 | null {
  const d = arrowStep(e.key, e.shiftKey);
  if (d) return pointOnScreenPlane(camera, pane, at, x + d[0], y + d[1]);
  const sign = e.key === 'PageUp' ? 1 : e.key === 'PageDown' ? -1 : 0;
  if (sign === 0) return null;
  const away = sub3(at, camera.position);
  if (!(len3(away) > 0)) return null;
  return add3(at, scale3(away, sign * (e.shiftKey ? DEPTH_BIG_STEP : DEPTH_STEP)));
}

/** The params patches for that move, or null when the key is not one of the handle's. */
export function handleKeyPatches3d(
  e: Pick<KeyboardEvent, 'key' | 'shiftKey'>,
  item: Handle3dItem,
  x: number,
  y: number,
  camera: Camera3d,
  pane: PaneSize,
  evaluation: Evaluation,
): NodePatch[] | null {
  const to = handleKeyTarget3d(e, item.at, x, y, camera, pane);
  return to ? dragPatches3d(evaluation, item, to) : null;
}
