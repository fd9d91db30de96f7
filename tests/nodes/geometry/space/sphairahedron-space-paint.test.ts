/**
 * The parameter-space view's pixels (docs/math-3d.md "The parameter-space view"): the class at
 * known points of each class, the quadtree painter agreeing with a construction at every pixel's
 * centre (so its boundaries are per pixel, not per cell), zb-only types painted in columns, and the
 * RGBA picture's boundary, axes and red point.
 */
import { describe, expect, it } from 'vitest';
import type { View } from '../../../../nodes/core/view.ts';
import { SPACE_CLASSES } from '../../../../nodes/geometry/space/sphairahedron-space.ts';
import {
  paintSpace,
  SpacePainter,
  spaceClassIndex,
  spacePixelParam,
  UNPAINTED,
} from '../../../../nodes/geometry/space/sphairahedron-space-paint.ts';
import {
  insetSpaceView,
  SPACE_COLOURS,
  spaceRgba,
  spaceScreen,
  spaceTicks,
} from '../../../../nodes/geometry/space/sphairahedron-space-picture.ts';
import { sphairahedronTypeById } from '../../../../nodes/geometry/space/sphairahedron-types.ts';

const cubeA = sphairahedronTypeById('cube-a')!;
const prismA = sphairahedronTypeById('prism-a')!;
const nameAt = (zb: number, zc: number, type = cubeA) => SPACE_CLASSES[spaceClassIndex(type, zb, zc)];

describe('parameter-space classes', () => {
  it('cube A: one known point of each class', () => {
    expect(nameAt(0.8, 0.3)).toBe('valid');
    expect(nameAt(1, 0)).toBe('bridge');
    expect(nameAt(-1, 0)).toBe('tunnel');
    expect(nameAt(1.2, -0.9)).toBe('bridge-tunnel');
    expect(nameAt(-1.5, 1.5)).toBe('degenerate');
  });

  it('a zb-only type ignores zc', () => {
    const [zb] = prismA.example;
    expect(nameAt(zb, 0, prismA)).toBe('valid');
    expect(nameAt(zb, 7, prismA)).toBe('valid');
  });
});

describe('SpacePainter', () => {
  // A window across cube A's valid region and its four neighbours.
  const view: View = { center: [0, 0], scale: 3.6 };
  const W = 36;
  const H = 28;

  it('paints every pixel the class built at its centre, but for one-pixel islands (boundaries per pixel)', () => {
    const classes = paintSpace(cubeA, view, W, H);
    const truth = new Uint8Array(W * H);
    for (let y = 0; y < H; y++)
      for (let x = 0; x < W; x++)
        truth[y * W + x] = spaceClassIndex(cubeA, ...spacePixelParam(view, W, H, x, y));
    // A pixel whose class no neighbour shares (the classifier's sampling speckle) touches no
    // built pixel of its class: the quadtree cannot find it. Every other pixel must be right.
    const island = (x: number, y: number) =>
      [
        [x - 1, y],
        [x + 1, y],
        [x, y - 1],
        [x, y + 1],
      ].every(([a, b]) => a! < 0 || b! < 0 || a! >= W || b! >= H || truth[b! * W + a!] !== truth[y * W + x]);
    const wrong: string[] = [];
    for (let y = 0; y < H; y++)
      for (let x = 0; x < W; x++)
        if (classes[y * W + x] !== truth[y * W + x] && !island(x, y)) wrong.push(`(${x}, ${y})`);
    expect(wrong).toEqual([]);
    // Several classes are on screen: the test is about boundaries, not one flat colour.
    expect(new Set(classes).size).toBeGreaterThanOrEqual(4);
  });

  it('paints in steps: coarse first, every pixel painted once done, far fewer builds than pixels', () => {
    const painter = new SpacePainter(cubeA, view, 64, 64);
    expect(painter.step(10)).toBe(false);
    expect(painter.classes.includes(UNPAINTED)).toBe(true);
    while (!painter.step(50));
    expect(painter.classes.includes(UNPAINTED)).toBe(false);
    expect(painter.builds).toBeLessThan(64 * 64);
  });

  it('a zb-only type: every column one class, its class at that zb', () => {
    const pview: View = { center: [prismA.example[0], 0], scale: 2 };
    const classes = paintSpace(prismA, pview, 20, 10);
    for (let x = 0; x < 20; x++) {
      const [zb] = spacePixelParam(pview, 20, 10, x, 0);
      for (let y = 0; y < 10; y++) expect(classes[y * 20 + x]).toBe(spaceClassIndex(prismA, zb, 0));
    }
  });
});

describe('spaceRgba', () => {
  it('colours classes, draws the boundary between them and the red point', () => {
    const classes = new Uint8Array([0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1]);
    const far: View = { center: [100, 100], scale: 1 };
    const rgba = spaceRgba(classes, 4, 4, far, { zcAxis: true });
    const px = (x: number, y: number) => [...rgba.slice((y * 4 + x) * 4, (y * 4 + x) * 4 + 3)];
    expect(px(0, 0)).toEqual([0x5f, 0xb8, 0x6a]);
    expect(px(1, 0)).toEqual([244, 244, 244]);
    expect(px(3, 0)).toEqual([0x4a, 0x90, 0xd9]);
    expect(SPACE_COLOURS.valid).toBe('#5fb86a');
    const big = new Uint8Array(40 * 40);
    const at: View = { center: [0, 0], scale: 4 };
    const withPoint = spaceRgba(big, 40, 40, at, { zcAxis: true, point: [1, 1] });
    const [sx, sy] = spaceScreen(at, 40, 40, 1, 1).map(Math.floor) as [number, number];
    expect([...withPoint.slice((sy * 40 + sx) * 4, (sy * 40 + sx) * 4 + 3)]).toEqual([229, 57, 53]);
  });

  it('ticks are round numbers inside the range', () => {
    expect(spaceTicks(-2.5, 2.5, 8)).toEqual([-2, -1, 0, 1, 2]);
    expect(spaceTicks(0.12, 0.5, 4)).toEqual([0.2, 0.3, 0.4, 0.5]);
  });

  it('insets the panel in the lower right corner, framed in white', () => {
    const image = { width: 60, height: 50, data: new Uint8ClampedArray(60 * 50 * 4) };
    insetSpaceView(image, { type: cubeA, zb: 0.8, zc: 0.3 });
    expect([...image.data.slice(0, 4)]).toEqual([0, 0, 0, 0]);
    const side = 20;
    const left = 60 - side - 2 - 4;
    expect([...image.data.slice(((50 - 4 - 1) * 60 + left) * 4, ((50 - 4 - 1) * 60 + left) * 4 + 4)]).toEqual(
      [255, 255, 255, 255],
    );
  });
});
