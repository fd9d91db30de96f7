/**
 * PNG encoding/decoding of 8-bit RGBA images with text chunks (the graph JSON travels in an iTXt
 * chunk keyed "kleinflow", so a PNG dropped back onto Kleinflow reopens its graph). Pure TS +
 * fflate: the same code serves the CLI (Node) and the browser.
 */
import { unzlibSync, zlibSync } from 'fflate';

const SIGNATURE = [137, 80, 78, 71, 13, 10, 26, 10];

const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

/** CRC-32 (ISO 3309, polynomial 0xEDB88320) over the chunk type and data. */
export function crc32(bytes: Uint8Array, crc = 0xffffffff): number {
  let c = crc;
  for (let i = 0; i < bytes.length; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return c >>> 0;
}

const ascii = (s: string) => Uint8Array.from(s, (ch) => ch.charCodeAt(0));
const utf8 = (s: string) => new TextEncoder().encode(s);

function chunk(type: string, data: Uint8Array): Uint8Array {
  const out = new Uint8Array(12 + data.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, data.length);
  out.set(ascii(type), 4);
  out.set(data, 8);
  view.setUint32(8 + data.length, (crc32(out.subarray(4, 8 + data.length)) ^ 0xffffffff) >>> 0);
  return out;
}

/** iTXt: keyword, 0, compression flag 0, method 0, empty language tag, 0, empty translated keyword, 0, UTF-8 text. */
function itxt(keyword: string, text: string): Uint8Array {
  const k = ascii(keyword);
  const t = utf8(text);
  const data = new Uint8Array(k.length + 5 + t.length);
  data.set(k, 0);
  data.set(t, k.length + 5);
  return chunk('iTXt', data);
}

export interface PngImage {
  readonly width: number;
  readonly height: number;
  /** RGBA, 8 bits per channel, row 0 at the top. */
  readonly data: Uint8Array | Uint8ClampedArray;
}

/** Encodes RGBA pixels as a PNG (filter type 0 per row, zlib level 6) with optional iTXt entries. */
export function encodePng(image: PngImage, text: Readonly<Record<string, string>> = {}): Uint8Array {
  const { width, height, data } = image;
  const ihdr = new Uint8Array(13);
  const v = new DataView(ihdr.buffer);
  v.setUint32(0, width);
  v.setUint32(4, height);
  ihdr.set([8, 6, 0, 0, 0], 8); // 8-bit, RGBA, deflate, adaptive filtering, no interlace
  const raw = new Uint8Array(height * (width * 4 + 1));
  for (let y = 0; y < height; y++) {
    raw[y * (width * 4 + 1)] = 0;
    raw.set(data.subarray(y * width * 4, (y + 1) * width * 4), y * (width * 4 + 1) + 1);
  }
  const parts = [
    Uint8Array.from(SIGNATURE),
    chunk('IHDR', ihdr),
    ...Object.entries(text).map(([k, t]) => itxt(k, t)),
    chunk('IDAT', zlibSync(raw, { level: 6 })),
    chunk('IEND', new Uint8Array(0)),
  ];
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

/** Reads the tEXt/iTXt (uncompressed) entries of a PNG; null when the bytes are not a PNG. */
export function readPngText(bytes: Uint8Array): Record<string, string> | null {
  if (bytes.length < 8 || SIGNATURE.some((b, i) => bytes[i] !== b)) return null;
  const out: Record<string, string> = {};
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let o = 8;
  while (o + 12 <= bytes.length) {
    const len = view.getUint32(o);
    const type = String.fromCharCode(...bytes.subarray(o + 4, o + 8));
    const data = bytes.subarray(o + 8, Math.min(bytes.length, o + 8 + len));
    if (type === 'tEXt' || type === 'iTXt') {
      const z = data.indexOf(0);
      if (z > 0) {
        const key = String.fromCharCode(...data.subarray(0, z));
        if (type === 'tEXt') out[key] = new TextDecoder('latin1').decode(data.subarray(z + 1));
        else if (data[z + 1] === 0) {
          // skip compression flag/method, language tag and translated keyword (both 0-terminated)
          let p = z + 3;
          p = data.indexOf(0, p) + 1;
          p = data.indexOf(0, p) + 1;
          if (p > 0) out[key] = new TextDecoder().decode(data.subarray(p));
        }
      }
    }
    if (type === 'IEND') break;
    o += 12 + len;
  }
  return out;
}

export const isPng = (bytes: Uint8Array): boolean =>
  bytes.length >= 8 && SIGNATURE.every((b, i) => bytes[i] === b);

/** The keyword of a tEXt/iTXt/zTXt chunk's data (Latin-1 up to the first 0 byte). */
const chunkKeyword = (data: Uint8Array): string => {
  const z = data.indexOf(0);
  return z > 0 ? String.fromCharCode(...data.subarray(0, z)) : '';
};

/**
 * A copy of a PNG with iTXt entries set: text chunks with the same keywords are removed and the
 * new entries go just before the first IDAT. Other chunks are copied byte for byte. Throws when
 * `bytes` is not a PNG (callers check with isPng first).
 */
export function setPngText(bytes: Uint8Array, text: Readonly<Record<string, string>>): Uint8Array {
  if (!isPng(bytes)) throw new Error('not a PNG file');
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const parts: Uint8Array[] = [bytes.subarray(0, 8)];
  const fresh = Object.entries(text).map(([k, t]) => itxt(k, t));
  let inserted = false;
  let o = 8;
  while (o + 12 <= bytes.length) {
    const len = view.getUint32(o);
    const type = String.fromCharCode(...bytes.subarray(o + 4, o + 8));
    const end = Math.min(bytes.length, o + 12 + len);
    const isText = type === 'tEXt' || type === 'iTXt' || type === 'zTXt';
    if ((type === 'IDAT' || type === 'IEND') && !inserted) {
      parts.push(...fresh);
      inserted = true;
    }
    if (!(isText && Object.hasOwn(text, chunkKeyword(bytes.subarray(o + 8, end)))))
      parts.push(bytes.subarray(o, end));
    if (type === 'IEND') break;
    o += 12 + len;
  }
  if (!inserted) parts.push(...fresh);
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let p = 0;
  for (const part of parts) {
    out.set(part, p);
    p += part.length;
  }
  return out;
}

/** Decodes an 8-bit RGBA, non-interlaced PNG as written by encodePng (filter types 0–4). For tests. */
export function decodePng(bytes: Uint8Array): PngImage {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let o = 8;
  let width = 0;
  let height = 0;
  const idat: Uint8Array[] = [];
  while (o + 12 <= bytes.length) {
    const len = view.getUint32(o);
    const type = String.fromCharCode(...bytes.subarray(o + 4, o + 8));
    const data = bytes.subarray(o + 8, o + 8 + len);
    if (type === 'IHDR') {
      width = view.getUint32(o + 8);
      height = view.getUint32(o + 12);
      if (data[8] !== 8 || data[9] !== 6 || data[12] !== 0)
        throw new Error('only 8-bit RGBA non-interlaced PNGs are supported');
    } else if (type === 'IDAT') idat.push(data);
    else if (type === 'IEND') break;
    o += 12 + len;
  }
  const all = new Uint8Array(idat.reduce((n, p) => n + p.length, 0));
  let p = 0;
  for (const d of idat) {
    all.set(d, p);
    p += d.length;
  }
  const raw = unzlibSync(all);
  const stride = width * 4;
  const out = new Uint8Array(height * stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)];
    for (let x = 0; x < stride; x++) {
      const cur = raw[y * (stride + 1) + 1 + x];
      const a = x >= 4 ? out[y * stride + x - 4] : 0;
      const b = y > 0 ? out[(y - 1) * stride + x] : 0;
      const c = x >= 4 && y > 0 ? out[(y - 1) * stride + x - 4] : 0;
      let pred = 0;
      if (f === 1) pred = a;
      else if (f === 2) pred = b;
      else if (f === 3) pred = (a + b) >> 1;
      else if (f === 4) {
        const pa = Math.abs(b - c);
        const pb = Math.abs(a - c);
        const pc = Math.abs(a + b - 2 * c);
        pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      out[y * stride + x] = (cur + pred) & 0xff;
    }
  }
  return { width, height, data: out };
}
