/** Fit frames the whole picture in panes of every shape. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Scene } from '../../../nodes/core/scene.ts';
import { pixelToWorld } from '../../../nodes/core/view.ts';
import { fitBounds, fitSquareView, openingView, pictureBounds } from '../../../src/viewport/fit-view.ts';

describe('fitBounds', () => {
  it('shows the whole box in a pane of any shape (property: its corners map inside the pane)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -10, max: 10, noNaN: true }),
        fc.double({ min: -10, max: 10, noNaN: true }),
        fc.double({ min: 0.01, max: 20, noNaN: true }),
        fc.double({ min: 0.01, max: 20, noNaN: true }),
        fc.integer({ min: 50, max: 3000 }),
        fc.integer({ min: 50, max: 3000 }),
        (x, y, w, h, width, height) => {
          const view = fitBounds({ min: [x, y], max: [x + w, y + h] }, { width, height });
          const lo = pixelToWorld(view, width, height, 0, 0, 0, 0);
          const hi = pixelToWorld(view, width, height, width, height, 0, 0);
          const eps = 1e-9 * (1 + Math.abs(x) + Math.abs(y) + w + h);
          expect(lo[0]).toBeLessThanOrEqual(x + eps);
          expect(lo[1]).toBeLessThanOrEqual(y + eps);
          expect(hi[0]).toBeGreaterThanOrEqual(x + w - eps);
          expect(hi[1]).toBeGreaterThanOrEqual(y + h - eps);
          // …and tightly: the box fills one dimension up to the margin.
          const fill = Math.max(w / (hi[0] - lo[0]), h / (hi[1] - lo[1]));
          expect(fill).toBeCloseTo(1 / 1.08, 6);
        },
      ),
      { seed: 1414, numRuns: 300 },
    );
  });
});

describe('fitSquareView', () => {
  const view = { center: [0.5, 0] as [number, number], scale: 2.2 };
  it('keeps the view in a wide pane and widens the world height in a tall one', () => {
    expect(fitSquareView(view, { width: 800, height: 600 })).toBe(view);
    expect(fitSquareView(view, { width: 390, height: 780 })).toEqual({ center: [0.5, 0], scale: 4.4 });
  });
});

describe('pictureBounds', () => {
  const base = { elements: [], overlays: [], clip: null } as unknown as Scene;
  it('is the clip disk when there is one, else the construction, else nothing', () => {
    expect(pictureBounds(base)).toBeNull();
    expect(pictureBounds({ ...base, clip: { c: [1, 0], r: 1 } })).toEqual({ min: [0, -1], max: [2, 1] });
    const withCircle = {
      ...base,
      overlays: [
        { nodeId: 'a', color: '', shape: { shape: 'circle', circle: { c: [0, 0], r: 2 } } },
        { nodeId: 'b', color: '', shape: { shape: 'point', at: [3, 1] } },
      ],
    } as unknown as Scene;
    expect(pictureBounds(withCircle)).toEqual({ min: [-2, -2], max: [3, 2] });
  });
});

describe('openingView', () => {
  const pane = { width: 320, height: 650 };
  const saved = { center: [0, 0] as [number, number], scale: 2.15 };
  it('keeps the saved (square-fitted) view when it shows the whole picture', () => {
    const bounds = { min: [-1, -1] as [number, number], max: [1, 1] as [number, number] };
    expect(openingView(saved, bounds, pane)).toEqual(fitSquareView(saved, pane));
    expect(openingView(saved, null, pane)).toEqual(fitSquareView(saved, pane));
  });
  it("frames the picture as Fit does when the saved view would crop it (the Apollonian gasket's mirrors)", () => {
    const bounds = { min: [-3.46, -3.73] as [number, number], max: [3.46, 2.73] as [number, number] };
    expect(openingView(saved, bounds, pane)).toEqual(fitBounds(bounds, pane));
  });
});
