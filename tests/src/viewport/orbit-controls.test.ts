/** The 3D view's gestures: a two-finger pinch keeps the point under the fingers; a drag orbits the expected way. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Camera3d } from '../../../nodes/core/scene-3d.ts';
import { dist3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { pointOnScreenPlane, project } from '../../../src/viewport/camera-3d.ts';
import { orbitDrag, pinch } from '../../../src/viewport/orbit-controls.ts';

const pane = { width: 390, height: 600 };
const camera: Camera3d = { position: [6, -8, 5], target: [0, 0, 0], fovDeg: 40 };

describe('pinch', () => {
  it('the point under the two fingers follows their midpoint; spreading them zooms in (property)', () => {
    const x = fc.double({ min: 0, max: 390, noNaN: true });
    const y = fc.double({ min: 0, max: 600, noNaN: true });
    fc.assert(
      fc.property(
        x,
        y,
        x,
        y,
        fc.double({ min: 20, max: 300, noNaN: true }),
        fc.double({ min: 0.3, max: 3, noNaN: true }),
        (x0, y0, x1, y1, d0, spread) => {
          const under = pointOnScreenPlane(camera, pane, camera.target, x0, y0) as Vec3;
          const c = pinch(camera, pane, [x0, y0], d0, [x1, y1], d0 * spread);
          const q = project(c, pane, under)!;
          expect(q.x).toBeCloseTo(x1, 4);
          expect(q.y).toBeCloseTo(y1, 4);
          expect(dist3(c.position, c.target)).toBeCloseTo(dist3(camera.position, camera.target) / spread, 6);
        },
      ),
      { seed: 42, numRuns: 200 },
    );
  });
});

describe('orbit drag', () => {
  it('dragging down raises the camera; dragging across the pane height turns half a turn', () => {
    expect(orbitDrag(camera, pane, 0, 50).position[2]).toBeGreaterThan(camera.position[2]);
    const turned = orbitDrag(camera, pane, pane.height, 0);
    expect(turned.position[0]).toBeCloseTo(-camera.position[0], 9);
    expect(turned.position[1]).toBeCloseTo(-camera.position[1], 9);
    expect(turned.position[2]).toBeCloseTo(camera.position[2], 9);
  });
});
