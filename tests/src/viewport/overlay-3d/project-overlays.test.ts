/** The 3D overlay's projection: sphere outlines are the true silhouette, boxes have 12 edges, nothing behind the camera is drawn. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Camera3d, Overlay3dItem } from '../../../../nodes/core/scene-3d.ts';
import { cross3, dist3, len3, sub3, type Vec3 } from '../../../../nodes/geometry/space/vec3.ts';
import { halfHeightAt1, rayThrough } from '../../../../src/viewport/camera-3d.ts';
import {
  itemNear,
  pathData,
  placeHandles3d,
  placeOverlays3d,
} from '../../../../src/viewport/overlay-3d/project-overlays.ts';

const pane = { width: 500, height: 400 };
const camera: Camera3d = { position: [6, -8, 5], target: [0, 0, 0], fovDeg: 40 };
const item = (shape: Overlay3dItem['shape']): Overlay3dItem => ({ nodeId: 'n', color: '#f00', shape });

/** Distance from point c to the ray from o along unit d. */
const rayDistance = (o: Vec3, d: Vec3, c: Vec3) => len3(cross3(sub3(c, o), d));

describe('sphere outlines', () => {
  it('every outline pixel looks along a ray tangent to the sphere (property)', () => {
    const coord = fc.double({ min: -3, max: 3, noNaN: true });
    fc.assert(
      fc.property(fc.tuple(coord, coord, coord), fc.double({ min: 0.1, max: 2, noNaN: true }), (c, r) => {
        const center = c as Vec3;
        const [placed] = placeOverlays3d(
          [item({ shape: 'sphere', sphere: { center, radius: r } })],
          camera,
          pane,
        );
        expect(placed.lines).toHaveLength(1);
        for (const [x, y] of placed.lines[0]) {
          expect(rayDistance(camera.position, rayThrough(camera, pane, x, y), center)).toBeCloseTo(r, 6);
        }
      }),
      { seed: 42, numRuns: 100 },
    );
  });

  it('a sphere at the target is a circle about the pane centre with the angular radius asin(R/D)', () => {
    const D = dist3(camera.position, camera.target);
    const [placed] = placeOverlays3d(
      [item({ shape: 'sphere', sphere: { center: [0, 0, 0], radius: 1 } })],
      camera,
      pane,
    );
    const expected = (Math.tan(Math.asin(1 / D)) / halfHeightAt1(camera)) * (pane.height / 2);
    for (const [x, y] of placed.lines[0]) expect(Math.hypot(x - 250, y - 200)).toBeCloseTo(expected, 6);
  });

  it('is not drawn when the eye is inside it or it is behind the camera', () => {
    const placed = placeOverlays3d(
      [
        item({ shape: 'sphere', sphere: { center: camera.position, radius: 1 } }),
        item({ shape: 'sphere', sphere: { center: [12, -16, 10], radius: 1 } }),
      ],
      camera,
      pane,
    );
    expect(placed.map((p) => p.lines.length)).toEqual([0, 0]);
  });
});

describe('points, planes, boxes', () => {
  it('a point is a dot; a plane a closed square and its normal; a box twelve edges', () => {
    const [point, plane, box] = placeOverlays3d(
      [
        item({ shape: 'point', at: [0, 0, 0] }),
        item({ shape: 'plane', plane: { point: [0, 0, 0], normal: [0, 0, 1] } }),
        item({ shape: 'box', center: [0, 0, 0], halfSize: [1, 1, 1] }),
      ],
      camera,
      pane,
    );
    expect(point.dot![0]).toBeCloseTo(250, 9);
    expect(point.dot![1]).toBeCloseTo(200, 9);
    expect(plane.lines).toHaveLength(2);
    expect(plane.lines[0]).toHaveLength(5);
    expect(plane.lines[0][4]).toEqual(plane.lines[0][0]);
    expect(box.lines).toHaveLength(12);
  });

  it('a box the camera is inside is clipped at the near plane, not dropped or flipped', () => {
    const [box] = placeOverlays3d(
      [item({ shape: 'box', center: camera.position, halfSize: [1, 1, 1] })],
      camera,
      pane,
    );
    expect(box.lines.length).toBeGreaterThan(0);
    expect(box.lines.length).toBeLessThan(12);
    for (const line of box.lines)
      for (const [x, y] of line) expect(Number.isFinite(x) && Number.isFinite(y)).toBe(true);
  });

  it('pathData writes SVG moves and lines', () => {
    expect(
      pathData([
        [1, 2],
        [3.25, 4],
      ]),
    ).toBe('M1.0 2.0L3.3 4.0');
  });
});

describe('handles', () => {
  it('are placed at their pixels, the nearest last, those behind the camera left out', () => {
    const handles = placeHandles3d(
      [
        { nodeId: 'a', handle: 'c', at: [0, 0, 0] },
        { nodeId: 'b', handle: 'c', at: [3, -4, 2.5] },
        { nodeId: 'c', handle: 'c', at: [12, -16, 10] },
      ],
      camera,
      pane,
    );
    expect(handles.map((h) => h.nodeId)).toEqual(['a', 'b']);
    expect(handles[0].x).toBeCloseTo(250, 9);
  });
});

describe('hover', () => {
  it('finds the item whose drawn lines or dot pass within the tolerance', () => {
    const items = placeOverlays3d(
      [
        {
          nodeId: 'ball',
          color: '#f00',
          shape: { shape: 'sphere', sphere: { center: [0, 0, 0], radius: 1 } },
        },
        { nodeId: 'dot', color: '#0f0', shape: { shape: 'point', at: [0, 0, 0] } },
      ],
      camera,
      pane,
    );
    const rim = items[0].lines[0][0];
    expect(itemNear(items, [rim[0] + 2, rim[1]], 5)).toBe('ball');
    expect(itemNear(items, [251, 201], 5)).toBe('dot');
    expect(itemNear(items, [5, 5], 5)).toBeNull();
  });
});
