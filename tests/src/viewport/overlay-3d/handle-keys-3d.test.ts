/** Keyboard moves of 3D handles: arrows go across the screen by the 2D steps, Page Up/Down along the line of sight. */
import { describe, expect, it } from 'vitest';
import type { Camera3d } from '../../../../nodes/core/scene-3d.ts';
import { cross3, dist3, len3, sub3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { project } from '../../../../src/viewport/camera-3d.ts';
import { HANDLE_BIG_STEP_PX, HANDLE_STEP_PX } from '../../../../src/viewport/overlay/handle-keys.ts';
import { DEPTH_STEP, handleKeyTarget3d } from '../../../../src/viewport/overlay-3d/handle-keys-3d.ts';

const pane = { width: 500, height: 400 };
const camera: Camera3d = { position: [6, -8, 5], target: [0, 0, 0], fovDeg: 40 };
const at: Vec3 = [0.5, -0.25, 1];
const screen = project(camera, pane, at)!;
const key = (k: string, shiftKey = false) =>
  handleKeyTarget3d({ key: k, shiftKey }, at, screen.x, screen.y, camera, pane);

describe('3D handle keys', () => {
  it.each([
    ['ArrowRight', false, HANDLE_STEP_PX, 0],
    ['ArrowLeft', true, -HANDLE_BIG_STEP_PX, 0],
    ['ArrowUp', false, 0, -HANDLE_STEP_PX],
    ['ArrowDown', false, 0, HANDLE_STEP_PX],
  ])('%s (Shift %s) moves the handle %d, %d pixels on screen', (k, shift, dx, dy) => {
    const to = key(k, shift)!;
    const p = project(camera, pane, to)!;
    expect(p.x - screen.x).toBeCloseTo(dx, 6);
    expect(p.y - screen.y).toBeCloseTo(dy, 6);
    // In the plane through the handle parallel to the screen: same depth along the view axis.
    expect(p.depth).toBeCloseTo(screen.depth, 9);
  });

  it('Page Up moves it away along its line of sight by a tenth of its distance, Page Down nearer', () => {
    const d0 = dist3(at, camera.position);
    for (const [k, sign] of [
      ['PageUp', 1],
      ['PageDown', -1],
    ] as const) {
      const to = key(k)!;
      expect(dist3(to, camera.position)).toBeCloseTo(d0 * (1 + sign * DEPTH_STEP), 9);
      // Still drawn where it was.
      expect(len3(cross3(sub3(to, camera.position), sub3(at, camera.position)))).toBeLessThan(1e-9);
      const p = project(camera, pane, to)!;
      expect(p.x).toBeCloseTo(screen.x, 6);
      expect(p.y).toBeCloseTo(screen.y, 6);
    }
  });

  it('other keys do not move it', () => {
    for (const k of ['Enter', 'a', 'Tab', 'Home']) expect(key(k)).toBeNull();
  });
});
