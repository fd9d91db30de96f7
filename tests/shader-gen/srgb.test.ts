import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { linearToSrgb, srgbToLinear, toLinear } from '../../shader-gen/srgb.ts';

const unit = fc.double({ min: 0, max: 1, noNaN: true });

describe('sRGB transfer functions', () => {
  it('fix 0 and 1 and match known values', () => {
    expect(srgbToLinear(0)).toBe(0);
    expect(srgbToLinear(1)).toBeCloseTo(1, 14);
    expect(linearToSrgb(1)).toBeCloseTo(1, 14);
    expect(srgbToLinear(0.5)).toBeCloseTo(0.21404, 5);
    expect(linearToSrgb(0.5)).toBeCloseTo(0.73536, 5);
    expect(srgbToLinear(0.04)).toBeCloseTo(0.04 / 12.92, 15); // linear segment
  });

  it('round trip linear → sRGB → linear and back', () => {
    fc.assert(
      fc.property(unit, (c) => {
        expect(srgbToLinear(linearToSrgb(c))).toBeCloseTo(c, 12);
        expect(linearToSrgb(srgbToLinear(c))).toBeCloseTo(c, 12);
      }),
      { seed: 42, numRuns: 500 },
    );
  });

  it('are continuous at the joint and increasing', () => {
    expect(Math.abs(linearToSrgb(0.0031308 + 1e-12) - linearToSrgb(0.0031308))).toBeLessThan(1e-7);
    expect(Math.abs(srgbToLinear(0.04045 + 1e-12) - srgbToLinear(0.04045))).toBeLessThan(1e-7);
    fc.assert(
      fc.property(unit, unit, (a, b) => {
        fc.pre(b - a > 1e-9);
        expect(linearToSrgb(a)).toBeLessThan(linearToSrgb(b));
      }),
      { seed: 42, numRuns: 200 },
    );
  });
});

describe('toLinear', () => {
  it('decodes each channel on its own', () => {
    expect(toLinear([0, 0.5, 1])).toEqual([0, srgbToLinear(0.5), srgbToLinear(1)]);
  });
});
