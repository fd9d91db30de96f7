import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec2 } from '../../../../nodes/core/values.ts';
import {
  circleRimVisible,
  clipLineToRect,
  placeHandles,
  pxPerWorld,
  type Screen,
  toCss,
  toWorld,
} from '../../../../src/viewport/overlay/screen.ts';

const screen: Screen = { view: { center: [1, 2], scale: 4 }, width: 800, height: 600 };

describe('world ↔ CSS pixels', () => {
  it('puts the view centre mid-pane, y up in the world and down on screen', () => {
    expect(toCss(screen, [1, 2])).toEqual([400, 300]);
    expect(toCss(screen, [1, 3])).toEqual([400, 150]);
    expect(toCss(screen, [2, 2])).toEqual([550, 300]);
    expect(pxPerWorld(screen)).toBe(150);
  });

  it('round-trips', () => {
    const coord = fc.double({ min: -1e4, max: 1e4, noNaN: true });
    fc.assert(
      fc.property(fc.tuple(coord, coord), (css) => {
        const back = toCss(screen, toWorld(screen, css as Vec2));
        expect(back[0]).toBeCloseTo(css[0], 6);
        expect(back[1]).toBeCloseTo(css[1], 6);
      }),
      { seed: 42, numRuns: 200 },
    );
  });
});

describe('clipLineToRect', () => {
  it('extends a short segment across the whole pane', () => {
    const seg = clipLineToRect([390, 300], [410, 300], 800, 600, 10)!;
    expect(seg).toEqual([
      [-10, 300],
      [810, 300],
    ]);
  });

  it('clips a diagonal to the rectangle and misses lines outside it', () => {
    const seg = clipLineToRect([0, 0], [1, 1], 800, 600, 0)!;
    expect(seg[0]).toEqual([0, 0]);
    expect(seg[1]).toEqual([600, 600]);
    expect(clipLineToRect([0, -50], [1, -50], 800, 600, 10)).toBeNull();
    expect(clipLineToRect([5, 5], [5, 5], 800, 600, 10)).toBeNull();
  });
});

describe('circleRimVisible', () => {
  it('is true when the rim crosses the pane, false when the pane is wholly inside or outside', () => {
    expect(circleRimVisible([400, 300], 100, 800, 600, 0)).toBe(true);
    expect(circleRimVisible([400, 300], 1e6, 800, 600, 0)).toBe(false);
    expect(circleRimVisible([-500, 300], 100, 800, 600, 0)).toBe(false);
    expect(circleRimVisible([-500, 300], 520, 800, 600, 0)).toBe(true);
  });
});

describe('placeHandles', () => {
  it('keeps only the first (upstream) of handles that coincide, coloured like its node', () => {
    const placed = placeHandles(
      [
        { nodeId: 'p', handle: 'point', at: [0, 0] },
        { nodeId: 'l', handle: 'a', at: [0, 0.001] }, // 0.15 px away: the same spot on screen
        { nodeId: 'l', handle: 'b', at: [1, 0] },
      ],
      (id) => (id === 'p' ? 'yellow' : 'teal'),
      screen,
    );
    expect(placed.map((h) => [h.item.nodeId, h.item.handle, h.color])).toEqual([
      ['p', 'point', 'yellow'],
      ['l', 'b', 'teal'],
    ]);
    expect(placed[1].at).toEqual([400, 600]);
  });
});
