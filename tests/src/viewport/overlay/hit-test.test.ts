import { describe, expect, it } from 'vitest';
import {
  distanceToShape,
  hitHandle,
  hitShape,
  type ScreenShape,
} from '../../../../src/viewport/overlay/hit-test.ts';

describe('distanceToShape', () => {
  it('measures to a point, to the whole infinite line, and to a circle rim from inside and out', () => {
    expect(distanceToShape([3, 4], { shape: 'point', at: [0, 0] })).toBe(5);
    // Far beyond the segment a→b: the line is infinite.
    expect(distanceToShape([500, 7], { shape: 'line', a: [0, 0], b: [10, 0] })).toBe(7);
    expect(distanceToShape([0, 0], { shape: 'line', a: [0, 10], b: [10, 0] })).toBeCloseTo(
      Math.SQRT2 * 5,
      12,
    );
    expect(distanceToShape([0, 13], { shape: 'circle', c: [0, 0], r: 10 })).toBe(3);
    expect(distanceToShape([0, 4], { shape: 'circle', c: [0, 0], r: 10 })).toBe(6);
  });
});

describe('hitHandle', () => {
  const handles: [number, number][] = [
    [100, 100],
    [106, 100],
    [300, 300],
  ];

  it('grabs the nearest handle within 8 px', () => {
    expect(hitHandle(handles, [104, 100], 8)).toBe(1);
    expect(hitHandle(handles, [101, 100], 8)).toBe(0);
    expect(hitHandle(handles, [300, 307.9], 8)).toBe(2);
  });

  it('misses beyond the radius', () => {
    expect(hitHandle(handles, [300, 308.1], 8)).toBe(-1);
    expect(hitHandle([], [0, 0], 8)).toBe(-1);
  });

  it('prefers the handle drawn last (on top) when two coincide', () => {
    expect(
      hitHandle(
        [
          [50, 50],
          [50, 50],
        ],
        [52, 50],
        8,
      ),
    ).toBe(1);
  });
});

describe('hitShape', () => {
  const shapes: ScreenShape[] = [
    { shape: 'circle', c: [200, 200], r: 100 },
    { shape: 'line', a: [0, 50], b: [10, 50] },
    { shape: 'point', at: [200, 200] },
  ];

  it('hovers a rim, a line far from its defining points, and a point within 5 px', () => {
    expect(hitShape(shapes, [303, 200], 5)).toBe(0);
    expect(hitShape(shapes, [700, 54], 5)).toBe(1);
    expect(hitShape(shapes, [202, 203], 5)).toBe(2);
  });

  it('ignores the inside of a circle and empty space', () => {
    expect(hitShape(shapes, [250, 200], 5)).toBe(-1);
    expect(hitShape(shapes, [700, 60], 5)).toBe(-1);
  });

  it('picks the nearest where shapes cross', () => {
    // The line y = 50 crosses nothing else; a point on both the rim (r=100 at y=100) and near the line.
    const crossing: ScreenShape[] = [
      { shape: 'circle', c: [0, 0], r: 50 },
      { shape: 'line', a: [-100, 52], b: [100, 52] },
    ];
    expect(hitShape(crossing, [0, 50.5], 5)).toBe(0);
    expect(hitShape(crossing, [0, 51.5], 5)).toBe(1);
  });
});
