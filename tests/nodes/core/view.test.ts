import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { pixelToWorld, sameView, type View, viewKeeping, worldToPixel } from '../../../nodes/core/view.ts';

const view: View = { center: [1, -2], scale: 4 };

describe('pixelToWorld (docs/math.md "Plane, view")', () => {
  it('maps pixel centres by center + ((px + 0.5 − W/2)/H, (py + 0.5 − H/2)/H)·scale', () => {
    // 200 × 100: a pixel is 0.04 world units
    expect(pixelToWorld(view, 200, 100, 0, 0)).toEqual([1 + (0.5 - 100) * 0.04, -2 + (0.5 - 50) * 0.04]);
    const mid = pixelToWorld(view, 200, 100, 100, 50, 0, 0);
    expect(mid).toEqual([1, -2]); // the canvas middle is the view centre
  });

  it('spans `scale` vertically and scale·W/H horizontally; y grows with py (origin bottom-left)', () => {
    const [x0, y0] = pixelToWorld(view, 300, 100, 0, 0, 0, 0);
    const [x1, y1] = pixelToWorld(view, 300, 100, 300, 100, 0, 0);
    expect(y1 - y0).toBeCloseTo(4, 12);
    expect(x1 - x0).toBeCloseTo(12, 12);
    expect(pixelToWorld(view, 10, 10, 0, 9)[1]).toBeGreaterThan(pixelToWorld(view, 10, 10, 0, 0)[1]);
  });

  it('worldToPixel is its inverse', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 4000 }),
        fc.integer({ min: 1, max: 4000 }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 0, max: 1, noNaN: true }),
        fc.double({ min: 1e-3, max: 1e3, noNaN: true }),
        (w, h, u, v, scale) => {
          const vw: View = { center: [0.3, -7], scale };
          const px = Math.floor(u * w);
          const py = Math.floor(v * h);
          const p = pixelToWorld(vw, w, h, px, py, 0.25, 0.75);
          const back = worldToPixel(vw, w, h, p);
          expect(back[0]).toBeCloseTo(px + 0.25, 6);
          expect(back[1]).toBeCloseTo(py + 0.75, 6);
        },
      ),
      { seed: 42, numRuns: 300 },
    );
  });
});

describe('viewKeeping', () => {
  it('keeps the world point at the pixel: pixelToWorld of the new view gives it back', () => {
    const coord = fc.double({ min: -1e3, max: 1e3, noNaN: true });
    fc.assert(
      fc.property(coord, coord, fc.double({ min: 1e-3, max: 1e3, noNaN: true }), (x, y, s) => {
        const next = viewKeeping([x, y], s, 300, 200, 40, 170);
        const [wx, wy] = pixelToWorld(next, 300, 200, 40, 170, 0, 0);
        expect(next.scale).toBe(s);
        expect(wx).toBeCloseTo(x, 6);
        expect(wy).toBeCloseTo(y, 6);
      }),
      { seed: 7, numRuns: 200 },
    );
  });

  it('sameView compares centre and scale', () => {
    expect(sameView(view, { center: [1, -2], scale: 4 })).toBe(true);
    expect(sameView(view, { center: [1, -2], scale: 5 })).toBe(false);
    expect(sameView(view, { center: [1, 2], scale: 4 })).toBe(false);
  });
});
