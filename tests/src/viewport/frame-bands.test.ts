/** How a slow full-size 3D sample is split into bands (src/viewport/frame-bands.ts). */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { BAND_MS, bandCount, bandRows, MAX_BANDS } from '../../../src/viewport/frame-bands.ts';

describe('bandCount', () => {
  it('is 1 for a fast sample or an unknown time, else about one band per BAND_MS', () => {
    expect(bandCount(0, 800)).toBe(1);
    expect(bandCount(Number.NaN, 800)).toBe(1);
    expect(bandCount(BAND_MS, 800)).toBe(1);
    expect(bandCount(BAND_MS * 2.5, 800)).toBe(3);
    expect(bandCount(1e9, 800)).toBe(MAX_BANDS);
    expect(bandCount(1e9, 5)).toBe(5); // at least one row a band
    expect(bandCount(10, 800, Number.POSITIVE_INFINITY)).toBe(1);
  });
});

describe('bandRows', () => {
  it('covers every row once, in order, each band non-empty and within one row of the others', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 4000 }),
        fc.integer({ min: 1, max: MAX_BANDS }),
        (rows, wanted) => {
          const n = Math.min(wanted, rows);
          let next = 0;
          const sizes: number[] = [];
          for (let i = 0; i < n; i++) {
            const [y0, y1] = bandRows(i, n, rows);
            expect(y0).toBe(next);
            expect(y1).toBeGreaterThan(y0);
            sizes.push(y1 - y0);
            next = y1;
          }
          expect(next).toBe(rows);
          expect(Math.max(...sizes) - Math.min(...sizes)).toBeLessThanOrEqual(1);
        },
      ),
      { seed: 51, numRuns: 300 },
    );
  });
});
