/** The 3D view's camera: projection ↔ rays, orbit keeps z up, zoom keeps the point under the cursor, pan follows the pointer. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Camera3d } from '../../../nodes/core/scene-3d.ts';
import { dist3, dot3, len3, sub3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import {
  cameraBasis,
  MAX_ELEVATION,
  orbit,
  pan,
  pointOnScreenPlane,
  project,
  rayThrough,
  zoomAbout,
} from '../../../src/viewport/camera-3d.ts';

const pane = { width: 640, height: 400 };
const camera: Camera3d = { position: [6, -8, 5], target: [0, 0, 0], fovDeg: 40 };
const coord = fc.double({ min: -20, max: 20, noNaN: true });
const vec = fc.tuple(coord, coord, coord) as fc.Arbitrary<Vec3>;
const cameras = fc
  .record({ position: vec, target: vec, fovDeg: fc.double({ min: 10, max: 120, noNaN: true }) })
  .filter((c) => dist3(c.position, c.target) > 0.1);
const pixel = fc.tuple(
  fc.double({ min: 0, max: 640, noNaN: true }),
  fc.double({ min: 0, max: 400, noNaN: true }),
);
const RUNS = { seed: 42, numRuns: 300 };

function elevation(c: Camera3d): number {
  const o = sub3(c.position, c.target);
  return Math.asin(o[2] / len3(o));
}

describe('camera basis and projection', () => {
  it('the target projects to the pane centre and "up" on screen is world z', () => {
    const p = project(camera, pane, camera.target)!;
    expect(p.x).toBeCloseTo(320, 9);
    expect(p.y).toBeCloseTo(200, 9);
    const above = project(camera, pane, [0, 0, 1])!;
    expect(above.y).toBeLessThan(200); // higher in the world → higher in the pane (smaller y)
    const { forward, right, up } = cameraBasis(camera);
    expect(dot3(forward, right)).toBeCloseTo(0, 12);
    expect(dot3(forward, up)).toBeCloseTo(0, 12);
    expect(right[2]).toBeCloseTo(0, 12); // the horizon stays level
  });

  it('the vertical field of view spans the pane height', () => {
    const top = rayThrough(camera, pane, 320, 0);
    const bottom = rayThrough(camera, pane, 320, 400);
    expect((Math.acos(dot3(top, bottom)) * 180) / Math.PI).toBeCloseTo(40, 9);
  });

  it('project inverts rayThrough (property)', () => {
    fc.assert(
      fc.property(cameras, pixel, fc.double({ min: 0.5, max: 50, noNaN: true }), (c, [x, y], s) => {
        const d = rayThrough(c, pane, x, y);
        const p: Vec3 = [c.position[0] + s * d[0], c.position[1] + s * d[1], c.position[2] + s * d[2]];
        const q = project(c, pane, p)!;
        expect(q.x).toBeCloseTo(x, 5);
        expect(q.y).toBeCloseTo(y, 5);
      }),
      RUNS,
    );
  });

  it('points behind the camera do not project', () => {
    expect(project(camera, pane, [12, -16, 10])).toBeNull();
  });

  it('looking straight down still has a basis', () => {
    const down: Camera3d = { position: [0, 0, 5], target: [0, 0, 0], fovDeg: 40 };
    const { right, up } = cameraBasis(down);
    expect(len3(right)).toBeCloseTo(1, 12);
    expect(len3(up)).toBeCloseTo(1, 12);
  });
});

describe('orbit', () => {
  it('keeps the target, the distance and z up; elevation is clamped (property)', () => {
    fc.assert(
      fc.property(cameras, coord, coord, (c, da, de) => {
        const o = orbit(c, da, de);
        expect(o.target).toEqual(c.target);
        expect(dist3(o.position, o.target)).toBeCloseTo(dist3(c.position, c.target), 6);
        expect(Math.abs(elevation(o))).toBeLessThanOrEqual(MAX_ELEVATION + 1e-9);
        expect(cameraBasis(o).right[2]).toBeCloseTo(0, 9);
      }),
      RUNS,
    );
  });

  it('a full turn of azimuth comes back; elevation moves the camera up', () => {
    const back = orbit(camera, 2 * Math.PI, 0);
    for (let i = 0; i < 3; i++) expect(back.position[i]).toBeCloseTo(camera.position[i], 9);
    expect(orbit(camera, 0, 0.2).position[2]).toBeGreaterThan(camera.position[2]);
    expect(elevation(orbit(camera, 0, 10))).toBeCloseTo(MAX_ELEVATION, 9);
  });
});

describe('zoom about the cursor', () => {
  it('the point under the cursor stays under the cursor (property)', () => {
    fc.assert(
      fc.property(cameras, pixel, fc.double({ min: 0.2, max: 5, noNaN: true }), (c, [x, y], k) => {
        const under = pointOnScreenPlane(c, pane, c.target, x, y)!;
        const z = zoomAbout(c, pane, x, y, k);
        const q = project(z, pane, under)!;
        expect(q.x).toBeCloseTo(x, 4);
        expect(q.y).toBeCloseTo(y, 4);
        expect(dist3(z.position, z.target)).toBeCloseTo(k * dist3(c.position, c.target), 6);
      }),
      RUNS,
    );
  });

  it('also keeps a point in front of or behind the target plane under the cursor', () => {
    const near = project(camera, pane, [1, -1, 1])!;
    const z = zoomAbout(camera, pane, near.x, near.y, 0.5);
    const q = project(z, pane, [1, -1, 1])!;
    expect(q.x).toBeCloseTo(near.x, 6);
    expect(q.y).toBeCloseTo(near.y, 6);
  });

  it('zooming at the centre moves the camera straight towards the target', () => {
    const z = zoomAbout(camera, pane, 320, 200, 0.5);
    for (let i = 0; i < 3; i++) {
      expect(z.target[i]).toBeCloseTo(camera.target[i], 9);
      expect(z.position[i]).toBeCloseTo(camera.position[i] / 2, 9);
    }
  });
});

describe('pan', () => {
  it('the point in the target plane under the pointer follows it (property)', () => {
    fc.assert(
      fc.property(
        cameras,
        pixel,
        fc.double({ min: -200, max: 200, noNaN: true }),
        coord,
        (c, [x, y], dx, dy) => {
          const grabbed = pointOnScreenPlane(c, pane, c.target, x, y)!;
          const q = project(pan(c, pane, dx, dy), pane, grabbed)!;
          expect(q.x).toBeCloseTo(x + dx, 4);
          expect(q.y).toBeCloseTo(y + dy, 4);
        },
      ),
      RUNS,
    );
  });
});

describe('pointOnScreenPlane (handle drags)', () => {
  it('lies under the pixel at the depth of the plane point (property)', () => {
    fc.assert(
      fc.property(cameras, pixel, (c, [x, y]) => {
        const h = c.target;
        const p = pointOnScreenPlane(c, pane, h, x, y)!;
        const q = project(c, pane, p)!;
        expect(q.x).toBeCloseTo(x, 4);
        expect(q.y).toBeCloseTo(y, 4);
        const f = cameraBasis(c).forward;
        expect(dot3(sub3(p, h), f)).toBeCloseTo(0, 6);
      }),
      RUNS,
    );
  });

  it('is null for a plane behind the camera', () => {
    expect(pointOnScreenPlane(camera, pane, [12, -16, 10], 320, 200)).toBeNull();
  });
});
