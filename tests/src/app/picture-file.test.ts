import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { fitPictureSize } from '../../../src/app/picture-file.ts';

describe('fitPictureSize', () => {
  it('keeps a picture that fits and shrinks a bigger one to the side limit', () => {
    expect(fitPictureSize(640, 480, 4096)).toEqual({ width: 640, height: 480 });
    expect(fitPictureSize(6000, 4000, 4096)).toEqual({ width: 4096, height: 2731 });
    expect(fitPictureSize(200, 5000, 4096)).toEqual({ width: 164, height: 4096 });
    expect(fitPictureSize(100000, 1, 4096)).toEqual({ width: 4096, height: 1 });
  });

  it('never exceeds the side, never goes below a pixel, and keeps the aspect within rounding', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 20000 }),
        fc.integer({ min: 1, max: 20000 }),
        fc.integer({ min: 16, max: 8192 }),
        (w, h, side) => {
          const f = fitPictureSize(w, h, side);
          expect(Math.max(f.width, f.height)).toBeLessThanOrEqual(Math.max(side, 1));
          expect(Math.min(f.width, f.height)).toBeGreaterThanOrEqual(1);
          if (w <= side && h <= side) expect(f).toEqual({ width: w, height: h });
          // Rounding moves each side by at most half a pixel.
          const s = Math.min(1, side / Math.max(w, h));
          expect(Math.abs(f.width - w * s)).toBeLessThanOrEqual(0.5 + 1e-9 + (w * s < 1 ? 1 : 0));
          expect(Math.abs(f.height - h * s)).toBeLessThanOrEqual(0.5 + 1e-9 + (h * s < 1 ? 1 : 0));
        },
      ),
      { seed: 21, numRuns: 500 },
    );
  });
});
