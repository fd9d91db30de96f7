import { describe, expect, it } from 'vitest';
import { BUILTIN_PICTURE } from '../../nodes/core/values.ts';
import { builtinPicture, resolvePicture, samplePicture } from '../../shader-gen/picture.ts';
import { placeUv, rotationPair } from '../../shader-gen/placement.ts';
import { srgbToLinear } from '../../shader-gen/srgb.ts';

/** A 2×2 picture: red, green / blue, white (row 0 at the top). */
const TINY = {
  width: 2,
  height: 2,
  data: new Uint8Array([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255]),
};

describe('the built-in picture shows its orientation', () => {
  const pic = builtinPicture();
  const texel = (x: number, y: number) => {
    // (x, y) in [−1, 1]², y up → row, column.
    const col = Math.floor(((x + 1) / 2) * pic.width);
    const row = Math.floor(((1 - y) / 2) * pic.height);
    const o = (row * pic.width + col) * 4;
    return [pic.data[o], pic.data[o + 1], pic.data[o + 2]];
  };
  it('has the size BUILTIN_PICTURE declares, opaque', () => {
    expect([pic.width, pic.height]).toEqual([BUILTIN_PICTURE.width, BUILTIN_PICTURE.height]);
    for (let i = 3; i < pic.data.length; i += 4) expect(pic.data[i]).toBe(255);
  });
  it('a white arrow points up (+y), a red dot sits top right, not mirrored', () => {
    expect(Math.min(...texel(0, 0.5))).toBeGreaterThan(230); // arrow head
    expect(Math.min(...texel(0, -0.5))).toBeGreaterThan(230); // shaft
    expect(Math.min(...texel(0.5, -0.5))).toBeLessThan(200); // beside the shaft: the checker
    const [r, g, b] = texel(0.72, 0.72);
    expect(r).toBeGreaterThan(200);
    expect(Math.max(g, b)).toBeLessThan(60);
    expect(texel(-0.72, 0.72)[1]).toBeGreaterThan(60); // the top-left corner has no red dot
  });
});

describe('samplePicture: bilinear in linear light, REPEAT wrap (what an SRGB8 texture gives)', () => {
  const lin = (v: number) => srgbToLinear(v / 255);
  it('a texel centre gives the texel, decoded to linear', () => {
    expect(samplePicture(TINY, 0.25, 0.25)).toEqual([lin(255), 0, 0]);
    expect(samplePicture(TINY, 0.75, 0.75)).toEqual([lin(255), lin(255), lin(255)]);
  });
  it('between texel centres it blends in linear light (not in sRGB)', () => {
    const mid = samplePicture(TINY, 0.5, 0.25); // red ↔ green
    expect(mid[0]).toBeCloseTo(0.5, 12);
    expect(mid[1]).toBeCloseTo(0.5, 12);
  });
  it('wraps: u = 0 is halfway between the last and the first column', () => {
    const edge = samplePicture(TINY, 0, 0.25); // green (last column) ↔ red (first)
    expect(edge[0]).toBeCloseTo(0.5, 12);
    expect(edge[1]).toBeCloseTo(0.5, 12);
    expect(samplePicture(TINY, 1.25, -0.75)).toEqual(samplePicture(TINY, 0.25, 0.25));
  });
  it('an unknown picture is reported by name, the built-in one needs no pixels', () => {
    expect(resolvePicture(BUILTIN_PICTURE.src, undefined)).toBe(builtinPicture());
    expect(() => resolvePicture('data:image/png;base64,AAAA', undefined)).toThrow(/not decoded/);
  });
});

describe('placeUv: picture rectangle → texture coordinates', () => {
  it('centre → (½, ½); top edge → v = 0; right edge → u = 1', () => {
    const [cos, sin] = rotationPair(0);
    expect(placeUv(1, 2, 4, 2, cos, sin, 1, 2)).toEqual([0.5, 0.5]);
    expect(placeUv(1, 2, 4, 2, cos, sin, 1, 3)).toEqual([0.5, 0]);
    expect(placeUv(1, 2, 4, 2, cos, sin, 3, 2)).toEqual([1, 0.5]);
  });
  it('turned 90° counter-clockwise, the picture’s top points to −x', () => {
    const [cos, sin] = rotationPair(Math.PI / 2);
    const [u, v] = placeUv(0, 0, 2, 2, cos, sin, -1, 0);
    expect(u).toBeCloseTo(0.5, 12);
    expect(v).toBeCloseTo(0, 12);
  });
});
