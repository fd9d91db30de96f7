import { describe, expect, it } from 'vitest';
import { DEFAULT_TILE, type Scene, type SceneElement, type TileSpec } from '../../nodes/core/scene.ts';
import type { Color } from '../../nodes/core/values.ts';
import { rasterize } from '../../shader-gen/raster.ts';
import { linearToSrgb } from '../../shader-gen/srgb.ts';
import { inv, refl } from './interpret-scenes.ts';

const RED: Color = [1, 0, 0];
const BLUE: Color = [0, 0, 1];
const parity = (even: Color, odd: Color, extra: Partial<TileSpec> = {}): TileSpec => ({
  ...DEFAULT_TILE,
  coloring: { mode: 'parity', even, odd },
  ...extra,
});

function makeScene(elements: SceneElement[], tile: TileSpec, extra: Partial<Scene> = {}): Scene {
  return {
    elements,
    tile,
    maxIterations: 50,
    samples: 1,
    clip: null,
    view: { center: [0, 0], scale: 4 },
    overlays: [],
    handles: [],
    renderNodeId: 'out',
    ...extra,
  };
}

const pixel = (r: { width: number; data: Uint8ClampedArray }, x: number, row: number) => {
  const o = (row * r.width + x) * 4;
  return [...r.data.slice(o, o + 4)];
};

describe('rasterize', () => {
  it('returns width × height RGBA pixels, opaque', () => {
    const r = rasterize(makeScene([], parity(RED, BLUE)), { width: 7, height: 5 });
    expect(r.width).toBe(7);
    expect(r.height).toBe(5);
    expect(r.data).toHaveLength(7 * 5 * 4);
    for (let i = 3; i < r.data.length; i += 4) expect(r.data[i]).toBe(255);
  });

  it('encodes sRGB: a flat sRGB colour comes back as the same 8-bit value', () => {
    const grey: Color = [128 / 255, 64 / 255, 200 / 255];
    const r = rasterize(makeScene([], parity(grey, grey)), { width: 3, height: 2, samples: 4 });
    for (let y = 0; y < 2; y++)
      for (let x = 0; x < 3; x++) expect(pixel(r, x, y)).toEqual([128, 64, 200, 255]);
  });

  it('averages samples in linear light (half white, half black → 188, not 128)', () => {
    // 1×1 image, view scale 1: sample 0 at (0, 0) (in the tile, even = white), sample 1 at about
    // (−0.245, −0.430), below the mirror y = −0.2 (depth 1, odd = black).
    const s = makeScene([refl([0, -0.2], [0, 1])], parity([1, 1, 1], [0, 0, 0]), {
      view: { center: [0, 0], scale: 1 },
    });
    const r = rasterize(s, { width: 1, height: 1, samples: 2 });
    const expected = Math.round(linearToSrgb(0.5) * 255);
    expect(expected).toBe(188);
    expect(pixel(r, 0, 0)).toEqual([188, 188, 188, 255]);
  });

  it('uses the scene sample count unless told otherwise', () => {
    const s = makeScene([refl([0, -0.2], [0, 1])], parity([1, 1, 1], [0, 0, 0]), {
      view: { center: [0, 0], scale: 1 },
      samples: 2,
    });
    expect(pixel(rasterize(s, { width: 1, height: 1 }), 0, 0)[0]).toBe(188);
    expect(pixel(rasterize(s, { width: 1, height: 1, samples: 1 }), 0, 0)[0]).toBe(255);
  });

  it('is deterministic', () => {
    const s = makeScene([inv([0.3, 0.1], 0.9), inv([-1, -0.5], 0.7), refl([0, -1.5], [0, 1])], DEFAULT_TILE, {
      samples: 3,
    });
    const a = rasterize(s, { width: 24, height: 16 });
    const b = rasterize(s, { width: 24, height: 16 });
    expect(Buffer.from(a.data).equals(Buffer.from(b.data))).toBe(true);
    expect(new Set(a.data).size).toBeGreaterThan(4); // not a flat image
  });

  it('puts y up: a tile y > 0 colours the TOP half of the rows', () => {
    // inside of the mirror = y < 0 (depth 1, blue); the tile y > 0 is red (depth 0)
    const r = rasterize(makeScene([refl([0, 0], [0, 1])], parity(RED, BLUE)), { width: 8, height: 6 });
    for (let row = 0; row < 6; row++) {
      for (let x = 0; x < 8; x++)
        expect(pixel(r, x, row)).toEqual(row < 3 ? [255, 0, 0, 255] : [0, 0, 255, 255]);
    }
  });

  it('keeps x to the right: a tile x > 1 colours the right columns', () => {
    // view 8 × 4 world units over 16 × 8 pixels: x > 1 is columns 10 … 15
    const r = rasterize(makeScene([refl([1, 0], [1, 0])], parity(RED, BLUE)), { width: 16, height: 8 });
    for (let x = 0; x < 16; x++) expect(pixel(r, x, 4)[0]).toBe(x >= 10 ? 255 : 0);
  });

  it('paints the background outside the clip disk', () => {
    const bg: Color = [0, 1, 0];
    const s = makeScene([], parity(RED, RED, { background: bg }), { clip: { c: [0, 0], r: 1 } });
    const r = rasterize(s, { width: 16, height: 16 }); // 0.25 world units per pixel
    expect(pixel(r, 0, 0)).toEqual([0, 255, 0, 255]);
    expect(pixel(r, 15, 15)).toEqual([0, 255, 0, 255]);
    expect(pixel(r, 2, 8)).toEqual([0, 255, 0, 255]); // x ≈ −1.375
    expect(pixel(r, 8, 8)).toEqual([255, 0, 0, 255]);
    expect(pixel(r, 5, 8)).toEqual([255, 0, 0, 255]); // x ≈ −0.625
  });

  it('points that never settle get the limit-set colour', () => {
    const s = makeScene([inv([-2, 0], 1), inv([2, 0], 1)], parity(RED, RED, { limitColor: [0, 0, 0] }), {
      maxIterations: 0,
      view: { center: [-2, 0], scale: 0.5 },
    });
    expect(pixel(rasterize(s, { width: 4, height: 4 }), 2, 2)).toEqual([0, 0, 0, 255]);
  });

  it('draws tile edges of constant pixel width along the mirrors', () => {
    const tile = parity(RED, RED, { edgeWidth: 2, edgeColor: [1, 1, 1] });
    // mirror y = 0 over 8 rows of 0.5 world units: the rows just above and below the line are edge
    const r = rasterize(makeScene([refl([0, 0], [0, 1])], tile), { width: 4, height: 8 });
    const col = [...Array(8).keys()].map((row) => pixel(r, 1, row)[1]);
    expect(col).toEqual([0, 0, 0, 255, 255, 0, 0, 0]);
  });

  it('stops when onProgress returns false', () => {
    const calls: number[] = [];
    const r = rasterize(makeScene([], parity(RED, RED)), {
      width: 2,
      height: 4,
      onProgress: (f) => {
        calls.push(f);
        return f < 0.5;
      },
    });
    expect(calls).toEqual([0.25, 0.5]);
    expect(pixel(r, 0, 3)).toEqual([255, 0, 0, 255]); // bottom row rendered first
    expect(pixel(r, 0, 0)).toEqual([0, 0, 0, 0]); // the top rows were never drawn
  });
});
