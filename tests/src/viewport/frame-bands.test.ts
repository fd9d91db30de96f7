/** How a slow full-size 3D sample is split into bands (src/viewport/frame-bands.ts). */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  BAND_MS,
  bandRows,
  firstBandRows,
  MAX_GROWTH,
  nextBandRows,
} from '../../../src/viewport/frame-bands.ts';

describe('firstBandRows', () => {
  it('is every row for a fast sample or an unknown time, else the rows that take about BAND_MS', () => {
    expect(firstBandRows(0, 800)).toBe(800);
    expect(firstBandRows(Number.NaN, 800)).toBe(800);
    expect(firstBandRows(BAND_MS, 800)).toBe(800);
    expect(firstBandRows(BAND_MS * 4, 800)).toBe(200);
    expect(firstBandRows(1e9, 800)).toBe(1); // at least one row a band
    expect(firstBandRows(10, 800, Number.POSITIVE_INFINITY)).toBe(800);
  });
});

describe('nextBandRows', () => {
  it('paces the next band to BAND_MS from the last one, growing at most MAX_GROWTH times', () => {
    expect(nextBandRows(40, BAND_MS * 2, 800)).toBe(20);
    expect(nextBandRows(40, BAND_MS, 800)).toBe(40);
    expect(nextBandRows(40, 1, 800)).toBe(40 * MAX_GROWTH);
    expect(nextBandRows(40, 1, 50)).toBe(50);
    expect(nextBandRows(3, 1e6, 800)).toBe(1);
    expect(nextBandRows(7, Number.NaN, 800)).toBe(7);
  });
});

describe('bandRows', () => {
  it('covers every row once from the top down, whatever the band sizes', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 4000 }),
        fc.array(fc.integer({ min: 1, max: 500 }), { minLength: 1, maxLength: 50 }),
        (height, sizes) => {
          let done = 0;
          let top = height;
          for (let i = 0; done < height; i++) {
            const [y0, y1] = bandRows(done, sizes[i % sizes.length], height);
            expect(y1).toBe(top);
            expect(y0).toBeGreaterThanOrEqual(0);
            expect(y1).toBeGreaterThan(y0);
            done += y1 - y0;
            top = y0;
          }
          expect(top).toBe(0);
        },
      ),
      { seed: 51, numRuns: 300 },
    );
  });
});
