import { describe, expect, it } from 'vitest';
import { countGifFrames, gifFrameBlocks, gifWriter } from '../../../src/io/gif.ts';

const frame = (shade: number) => {
  const data = new Uint8Array(8 * 6 * 4);
  for (let i = 0; i < data.length; i += 4) data.set([shade, (i / 4) * 5, 255 - shade, 255], i);
  return { width: 8, height: 6, data };
};

describe('gif', () => {
  it('writes one image per frame, loops, and is the same bytes for the same frames', () => {
    const write = () => {
      const w = gifWriter(10);
      for (const s of [0, 80, 160]) w.addFrame(frame(s));
      return w.finish();
    };
    const a = write();
    expect(String.fromCharCode(...a.subarray(0, 6))).toBe('GIF89a');
    expect(countGifFrames(a)).toBe(3);
    const [f0, f1] = gifFrameBlocks(a);
    expect(f0).not.toEqual(f1);
    expect(a).toEqual(write());
    expect(new TextDecoder().decode(a)).toContain('NETSCAPE2.0'); // the looping extension
  });

  it('refuses an empty GIF and bytes that are not one', () => {
    expect(() => gifWriter(10).finish()).toThrow(/at least one frame/);
    expect(() => countGifFrames(new Uint8Array([1, 2, 3, 4, 5, 6]))).toThrow(/not a GIF/);
  });
});
