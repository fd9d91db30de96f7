import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { cropToAspect } from '../../../src/viewport/live-textures.ts';

describe('a live frame cropped to its picture’s aspect', () => {
  it('a 640 × 480 camera into a square picture: the centred 480 × 480', () => {
    expect(cropToAspect(640, 480, 1)).toEqual({ x: 80, y: 0, width: 480, height: 480 });
  });

  it('a 640 × 480 camera into a 16:9 picture: full width, centred rows', () => {
    expect(cropToAspect(640, 480, 16 / 9)).toEqual({ x: 0, y: 60, width: 640, height: 360 });
  });

  it('always inside the frame, centred, and of the asked aspect to within a pixel', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 4096 }),
        fc.integer({ min: 1, max: 4096 }),
        fc.double({ min: 0.05, max: 20, noNaN: true }),
        (w, h, aspect) => {
          const c = cropToAspect(w, h, aspect);
          expect(c.x).toBeGreaterThanOrEqual(0);
          expect(c.y).toBeGreaterThanOrEqual(0);
          expect(c.x + c.width).toBeLessThanOrEqual(w);
          expect(c.y + c.height).toBeLessThanOrEqual(h);
          expect(Math.abs(w - c.width - 2 * c.x)).toBeLessThanOrEqual(1);
          // One side is full; the other is that side × aspect, rounded.
          expect(c.width === w || c.height === h).toBe(true);
          if (c.width === w && c.height < h) expect(Math.abs(c.height - w / aspect)).toBeLessThanOrEqual(1);
          if (c.height === h && c.width < w) expect(Math.abs(c.width - h * aspect)).toBeLessThanOrEqual(1);
        },
      ),
      { seed: 17, numRuns: 300 },
    );
  });
});
