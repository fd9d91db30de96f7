import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { timelinePosition } from '../../../src/viewport/live-media.ts';

describe('a video on the animation timeline', () => {
  it('shows the time modulo its length', () => {
    expect(timelinePosition(0.4, 1.2)).toBeCloseTo(0.4, 12);
    expect(timelinePosition(2.9, 1.2)).toBeCloseTo(0.5, 12);
    expect(timelinePosition(-0.2, 1)).toBeCloseTo(0.8, 12);
  });

  it('has no place while its length is unknown (a recorded WebM before its end was read)', () => {
    expect(timelinePosition(1, Number.POSITIVE_INFINITY)).toBeNull();
    expect(timelinePosition(1, Number.NaN)).toBeNull();
    expect(timelinePosition(1, 0)).toBeNull();
  });

  it('always lands in [0, duration) and repeats every duration', () => {
    fc.assert(
      fc.property(
        fc.double({ min: -1e4, max: 1e4, noNaN: true }),
        fc.double({ min: 0.1, max: 600, noNaN: true }),
        (t, d) => {
          const p = timelinePosition(t, d)!;
          expect(p).toBeGreaterThanOrEqual(0);
          expect(p).toBeLessThanOrEqual(d);
          const q = timelinePosition(t + d, d)!;
          expect(Math.min(Math.abs(p - q), d - Math.abs(p - q))).toBeLessThan(
            1e-6 * Math.max(1, Math.abs(t)),
          );
        },
      ),
      { seed: 17, numRuns: 300 },
    );
  });
});
