import { describe, expect, it } from 'vitest';
import { DEFAULT_TILE, type TileSpec } from '../../nodes/core/scene.ts';
import { cosinePalette, depthColour, hsvToRgb, shade } from '../../shader-gen/colour.ts';
import { toLinear } from '../../shader-gen/srgb.ts';

describe('palettes', () => {
  it('HSV hues: red, green, blue, wrap-around and grey', () => {
    expect(hsvToRgb(0, 1, 1)).toEqual([1, 0, 0]);
    const g = hsvToRgb(1 / 3, 1, 1);
    expect(g[0]).toBeCloseTo(0, 12);
    expect(g[1]).toBeCloseTo(1, 12);
    expect(g[2]).toBeCloseTo(0, 12);
    const b = hsvToRgb(2 / 3, 1, 1);
    expect(b[2]).toBeCloseTo(1, 12);
    expect(b[0]).toBeCloseTo(0, 12);
    expect(hsvToRgb(1 / 6, 1, 1).map((v) => Number(v.toFixed(12)))).toEqual([1, 1, 0]); // yellow
    expect(hsvToRgb(1.25, 0.5, 0.8)).toEqual(hsvToRgb(0.25, 0.5, 0.8));
    expect(hsvToRgb(0.7, 0, 0.4)).toEqual([0.4, 0.4, 0.4]);
  });

  it('the cosine palette is a + b·cos(2π(c·t + d)), clamped', () => {
    const c = DEFAULT_TILE.coloring as Extract<TileSpec['coloring'], { mode: 'cosine' }>;
    const at0 = cosinePalette(c.a, c.b, c.c, c.d, 0);
    expect(at0[0]).toBeCloseTo(1, 12);
    expect(at0[1]).toBeCloseTo(0.5 + 0.5 * Math.cos(2 * Math.PI * 0.33), 12);
    expect(cosinePalette([0.9, 0, 0], [0.5, 0.5, 0.5], [0, 0, 0], [0, 0.5, 0], 3)).toEqual([1, 0, 0.5]);
  });

  it('depth colours per mode', () => {
    expect(depthColour({ mode: 'parity', even: [1, 1, 1], odd: [0, 0, 0] }, 4)).toEqual([1, 1, 1]);
    expect(depthColour({ mode: 'parity', even: [1, 1, 1], odd: [0, 0, 0] }, 7)).toEqual([0, 0, 0]);
    const hsv = { mode: 'depth-hsv', hueOffset: 0.01, hueStep: 0.05, saturation: 1, value: 1 } as const;
    expect(depthColour(hsv, 3)).toEqual(hsvToRgb(0.16, 1, 1));
  });
});

describe('shade (linear light)', () => {
  const tile: TileSpec = {
    ...DEFAULT_TILE,
    coloring: { mode: 'parity', even: [1, 0, 0], odd: [0, 0, 1] },
    limitColor: [0, 1, 0],
    background: [0.5, 0.5, 0.5],
    edgeWidth: 2,
    edgeColor: [1, 1, 1],
  };
  const base = {
    escaped: true,
    depth: 0,
    clipped: false,
    edgePixels: Number.POSITIVE_INFINITY,
    x: 0,
    y: 0,
    limitPixels: Number.POSITIVE_INFINITY,
    seed: -1,
  };

  it('clip → background, not escaped → limit colour, else the depth colour', () => {
    expect(shade(tile, { ...base, clipped: true })).toEqual(toLinear([0.5, 0.5, 0.5]));
    expect(shade(tile, { ...base, escaped: false })).toEqual([0, 1, 0]);
    expect(shade(tile, { ...base, depth: 1 })).toEqual([0, 0, 1]);
  });

  it('draws edges of the given pixel width, antialiased over one pixel', () => {
    expect(shade(tile, { ...base, edgePixels: 0 })).toEqual([1, 1, 1]);
    expect(shade(tile, { ...base, edgePixels: 0.5 })).toEqual([1, 1, 1]);
    expect(shade(tile, { ...base, edgePixels: 1.5 })).toEqual([1, 0, 0]);
    const mid = shade(tile, { ...base, edgePixels: 1 });
    expect(mid[0]).toBeCloseTo(1, 12);
    expect(mid[1]).toBeCloseTo(0.5, 12);
    expect(shade({ ...tile, edgeWidth: 0 }, { ...base, edgePixels: 0 })).toEqual([1, 0, 0]);
  });
});
