/** Hand-made PNG bytes for the limit tests: chunks laid out as the PNG specification says. */
import { encodePng, pngChunk } from '../../../../src/io/png.ts';

export { pngChunk };

const ascii = (s: string) => Uint8Array.from(s, (c) => c.charCodeAt(0));

/** tEXt data: keyword, 0, Latin-1 text. */
export const textData = (keyword: Uint8Array | string, text: string): Uint8Array => {
  const k = typeof keyword === 'string' ? ascii(keyword) : keyword;
  const t = ascii(text);
  const out = new Uint8Array(k.length + 1 + t.length);
  out.set(k);
  out.set(t, k.length + 1);
  return out;
};

/** A 1×1 PNG with `extra` chunks inserted just after its IHDR. */
export function pngWith(extra: readonly Uint8Array[]): Uint8Array {
  const base = encodePng({ width: 1, height: 1, data: new Uint8Array(4) });
  const ihdrEnd = 8 + 12 + 13;
  const size = base.length + extra.reduce((n, c) => n + c.length, 0);
  const out = new Uint8Array(size);
  out.set(base.subarray(0, ihdrEnd));
  let at = ihdrEnd;
  for (const c of extra) {
    out.set(c, at);
    at += c.length;
  }
  out.set(base.subarray(ihdrEnd), at);
  return out;
}
