import { describe, expect, it } from 'vitest';
import { sampleOffset } from '../../shader-gen/view.ts';

describe('sampleOffset', () => {
  it('sample 0 is the pixel centre', () => {
    expect(sampleOffset(0)).toEqual([0.5, 0.5]);
  });

  it('every offset lies in [0, 1)², and the first 256 are distinct and well spread', () => {
    const offsets = Array.from({ length: 256 }, (_, k) => sampleOffset(k));
    for (const [x, y] of offsets) {
      expect(x >= 0 && x < 1 && y >= 0 && y < 1).toBe(true);
    }
    expect(new Set(offsets.map((o) => o.join(','))).size).toBe(256);
    // low discrepancy: each quadrant of the pixel gets about a quarter of the samples
    for (const [qx, qy] of [
      [0, 0],
      [0, 1],
      [1, 0],
      [1, 1],
    ]) {
      const n = offsets.filter(([x, y]) => Math.floor(x * 2) === qx && Math.floor(y * 2) === qy).length;
      expect(n).toBeGreaterThan(56);
      expect(n).toBeLessThan(72);
    }
    const mean = offsets.reduce((m, [x, y]) => [m[0] + x / 256, m[1] + y / 256], [0, 0]);
    expect(mean[0]).toBeCloseTo(0.5, 1);
    expect(mean[1]).toBeCloseTo(0.5, 1);
  });
});
