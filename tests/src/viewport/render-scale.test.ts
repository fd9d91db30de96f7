/**
 * The 3D pane's dynamic resolution policy: the scale chosen from measured frame times, its bounds,
 * its hysteresis band and its settling to a fixed point under a pixel-proportional cost model.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  interacting,
  nextRenderScale,
  DEFAULT_SCALE_POLICY as P,
  scaledSize,
} from '../../../src/viewport/render-scale.ts';

const RUNS = { seed: 1313, numRuns: 300 };

describe('nextRenderScale', () => {
  it('a 2 s full-size frame (SwiftShader) drops to a scale whose predicted frame fits the band', () => {
    const s = nextRenderScale(1, { ms: 2000, scale: 1 });
    expect(s).toBeLessThan(1);
    expect(2000 * s ** 2).toBeLessThanOrEqual(P.highMs);
    expect(s / P.quantum).toBeCloseTo(Math.round(s / P.quantum), 9); // a multiple of the quantum
  });

  it('keeps the scale while the predicted frame time stays inside the band (hysteresis)', () => {
    expect(nextRenderScale(0.25, { ms: 31, scale: 0.25 })).toBe(0.25);
    expect(nextRenderScale(0.25, { ms: 59, scale: 0.25 })).toBe(0.25);
    // measured at full size after settling: 800 ms × (1/4)² = 50 ms, inside: unchanged
    expect(nextRenderScale(0.25, { ms: 800, scale: 1 })).toBe(0.25);
  });

  it('leaves the band in both directions, going up by at most maxStepUp', () => {
    expect(nextRenderScale(0.25, { ms: 200, scale: 0.25 })).toBeLessThan(0.25);
    const up = nextRenderScale(0.25, { ms: 2, scale: 0.25 });
    expect(up).toBeGreaterThan(0.25);
    expect(up).toBeLessThanOrEqual(0.25 * P.maxStepUp);
  });

  it('fast frames stay at full size; a hopeless one stops at the smallest scale', () => {
    expect(nextRenderScale(1, { ms: 16, scale: 1 })).toBe(1);
    expect(nextRenderScale(1, { ms: 1e6, scale: 1 })).toBe(P.minScale);
  });

  it('ignores a measurement that is not a positive finite time', () => {
    for (const ms of [0, -5, Number.NaN, Number.POSITIVE_INFINITY])
      expect(nextRenderScale(0.5, { ms, scale: 1 })).toBe(0.5);
  });

  it('stays within [minScale, 1] for any measurement (property)', () => {
    fc.assert(
      fc.property(
        fc.double({ min: P.minScale, max: 1, noNaN: true }),
        fc.double({ min: 0.001, max: 1e6, noNaN: true }),
        fc.double({ min: P.minScale, max: 1, noNaN: true }),
        (current, ms, scale) => {
          const s = nextRenderScale(current, { ms, scale });
          return s >= P.minScale && s <= 1;
        },
      ),
      RUNS,
    );
  });

  it('with frame time ∝ pixels it settles, within the band or at a bound (property)', () => {
    fc.assert(
      fc.property(fc.double({ min: 1, max: 1e5, noNaN: true }), (fullMs) => {
        const time = (s: number) => fullMs * s * s;
        let s = 1;
        const seen: number[] = [];
        for (let i = 0; i < 30; i++) {
          seen.push(s);
          s = nextRenderScale(s, { ms: time(s), scale: s });
        }
        // settled: the last steps change nothing (no oscillation)
        expect(seen.slice(-5).every((x) => x === s)).toBe(true);
        // too slow only at the smallest scale; never reduced without need
        if (time(s) > P.highMs) expect(s).toBe(P.minScale);
        if (s < 1) expect(time(Math.min(1, s + P.quantum))).toBeGreaterThan(P.lowMs);
      }),
      RUNS,
    );
  });
});

describe('interacting and scaledSize', () => {
  it('counts as interaction until settleMs of stillness', () => {
    expect(interacting(0)).toBe(true);
    expect(interacting(P.settleMs - 1)).toBe(true);
    expect(interacting(P.settleMs)).toBe(false);
  });

  it('full size at scale 1; at least one pixel when reduced', () => {
    expect(scaledSize(640, 360, 1)).toEqual({ width: 640, height: 360 });
    expect(scaledSize(640, 360, 0.25)).toEqual({ width: 160, height: 90 });
    expect(scaledSize(5, 3, 1 / 8)).toEqual({ width: 1, height: 1 });
  });
});
