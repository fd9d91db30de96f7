/**
 * The 3D colourings by a measure of the hit point (shader-gen/space/shade-3d.ts, docs/math-3d.md
 * §9 "Colour"): m = |p| or atan2(p_y, p_x)/2π, t = offset + frequency·m, then the cosine palette
 * or the seed colour's hue turned by t.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { cosinePalette, hsvToRgb } from '../../../shader-gen/colour.ts';
import {
  baseColour,
  type MeasureColoring3d,
  measure3d,
  measureColour3d,
  rgbToHsv,
} from '../../../shader-gen/space/shade-3d.ts';

const { a, b, c, d } = PALETTES.rainbow!;
const coloring = (
  mode: 'distance' | 'argument',
  wheel = false,
  frequency = 1,
  offset = 0,
): MeasureColoring3d => ({
  mode,
  wheel,
  a,
  b,
  c,
  d,
  frequency,
  offset,
});
const SEED = [0.9, 0.6, 0.3] as const;
const coord = fc.double({ min: -5, max: 5, noNaN: true });
const point = fc.tuple(coord, coord, coord) as fc.Arbitrary<Vec3>;
const close = (x: readonly number[], y: readonly number[]) =>
  x.forEach((v, k) => {
    expect(v).toBeCloseTo(y[k]!, 9);
  });

describe('3D colour by a measure of the hit point', () => {
  it('measures the distance from the origin and the argument about the z axis in turns', () => {
    expect(measure3d('distance', [3, 4, 12])).toBeCloseTo(13, 12);
    expect(measure3d('argument', [1, 0, 7])).toBe(0);
    expect(measure3d('argument', [0, 2, -1])).toBeCloseTo(0.25, 12);
    expect(measure3d('argument', [-1, 0, 0])).toBeCloseTo(0.5, 12);
    expect(measure3d('argument', [1, -1, 0])).toBeCloseTo(-0.125, 12);
  });

  it('reads the palette at t = offset + frequency·m', () => {
    const p: Vec3 = [0.3, -0.4, 1.2];
    const col = coloring('distance', false, 2.5, 0.1);
    close(measureColour3d(col, SEED, p), cosinePalette(a, b, c, d, 0.1 + 2.5 * 1.3));
    const wheel = coloring('argument', true, 3, 0.2);
    const [h, s, v] = rgbToHsv(SEED);
    close(
      measureColour3d(wheel, SEED, p),
      hsvToRgb(h + 0.2 + (3 * Math.atan2(-0.4, 0.3)) / (2 * Math.PI), s, v),
    );
  });

  it('by formula: the palette of a formula of the hit point and the depth; not finite is 0', () => {
    const f = (formula: string) => ({
      ...coloring('distance', false, 1, 0.1),
      mode: 'formula' as const,
      formula,
    });
    const p: Vec3 = [0.5, -1, 2];
    close(baseColour(f('n / 4 + z'), SEED, 3, p, [9, 9, 9]), cosinePalette(a, b, c, d, 0.1 + 0.75 + 2));
    close(baseColour(f('x * y'), SEED, 0, p, [9, 9, 9]), cosinePalette(a, b, c, d, 0.1 - 0.5));
    close(baseColour(f('1 / (n - 3)'), SEED, 3, p, p), cosinePalette(a, b, c, d, 0.1)); // ∞ → 0
    close(baseColour(f('sqrt(-1)'), SEED, 3, p, p), cosinePalette(a, b, c, d, 0.1)); // NaN → 0
  });

  it('is the colouring baseColour gives for the hit point, not the final point', () => {
    const col = coloring('distance', false, 1.7);
    close(baseColour(col, SEED, 5, [1, 2, 2], [9, 9, 9]), measureColour3d(col, SEED, [1, 2, 2]));
  });

  it('by distance: the same on every sphere about the origin; by argument: the same along every half-plane of the z axis', () => {
    fc.assert(
      fc.property(point, fc.double({ min: 0.1, max: 10, noNaN: true }), coord, (p, k, z) => {
        const r = Math.hypot(p[0], p[1], p[2]);
        fc.pre(r > 1e-6 && Math.hypot(p[0], p[1]) > 1e-6);
        const dist = coloring('distance', false, 0.8);
        close(measureColour3d(dist, SEED, p), measureColour3d(dist, SEED, [r, 0, 0]));
        const arg = coloring('argument', true, 2);
        close(measureColour3d(arg, SEED, p), measureColour3d(arg, SEED, [k * p[0], k * p[1], z]));
      }),
      { seed: 3325, numRuns: 200 },
    );
  });

  it('by argument with whole cycles per turn, the colour joins up across the negative x axis', () => {
    for (const cycles of [1, 2, 3]) {
      const col = coloring('argument', false, cycles);
      const above = measureColour3d(col, SEED, [-1, 1e-9, 0]);
      const below = measureColour3d(col, SEED, [-1, -1e-9, 0]);
      above.forEach((v, k) => {
        expect(Math.abs(v - below[k]!)).toBeLessThan(1e-6);
      });
    }
  });
});
