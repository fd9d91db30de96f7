/**
 * PNG encoding/decoding of 8-bit RGBA images with text chunks (the graph JSON travels in an iTXt
 * chunk keyed "kleinflow", so a PNG dropped back onto Kleinflow reopens its graph). Pure TS,
 * fflate and fast-png: the same code serves the CLI (Node) and the browser. Decoding pixels is
 * fast-png's; the writer and the text reader walk chunk headers only (no pixel is decoded to read
 * a graph) and take their limits from the caller (Kleinflow's policy: src/io/png-graph.ts).
 */
import { convertIndexedToRgb, decode } from 'fast-png';
import { zlibSync } from 'fflate';

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

/** One chunk as the PNG specification lays it out: length, type, data, CRC over type and data. */
export function pngChunk(type: string, data: Uint8Array): Uint8Array {
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
  return pngChunk('iTXt', data);
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
    pngChunk('IHDR', ihdr),
    ...Object.entries(text).map(([k, t]) => itxt(k, t)),
    pngChunk('IDAT', zlibSync(raw, { level: 6 })),
    pngChunk('IEND', new Uint8Array(0)),
  ];
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

export const isPng = (bytes: Uint8Array): boolean =>
  bytes.length >= 8 && SIGNATURE.every((b, i) => bytes[i] === b);

/** The PNG specification's longest keyword of a text chunk (tEXt, zTXt, iTXt), in bytes. */
export const PNG_KEYWORD_BYTES = 79;

/** What a caller lets one PNG hold before it is refused: all its chunks, and one text entry's bytes. */
export interface PngTextLimits {
  readonly chunks: number;
  readonly textBytes: number;
}

const NO_LIMITS: PngTextLimits = { chunks: Number.POSITIVE_INFINITY, textBytes: Number.POSITIVE_INFINITY };

/** A PNG past a limit, or with a malformed text chunk: one line saying which chunk and why. */
export class PngProblem extends Error {}

interface Chunk {
  /** Where the chunk starts (its length field) and ends (after its CRC, clipped to the file). */
  readonly start: number;
  readonly end: number;
  readonly type: string;
  readonly data: Uint8Array;
}

/**
 * The chunks of a PNG after its signature, up to IEND: headers only, no data copied or decoded.
 * Throws PngProblem past `maxChunks` chunks.
 */
function* chunks(bytes: Uint8Array, maxChunks: number): Generator<Chunk> {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let o = 8;
  for (let n = 1; o + 12 <= bytes.length; n++) {
    if (n > maxChunks)
      throw new PngProblem(`it has more than ${maxChunks.toLocaleString('en')} chunks, the limit`);
    const len = view.getUint32(o);
    const type = String.fromCharCode(bytes[o + 4], bytes[o + 5], bytes[o + 6], bytes[o + 7]);
    const end = Math.min(bytes.length, o + 12 + len);
    yield { start: o, end, type, data: bytes.subarray(o + 8, Math.min(bytes.length, o + 8 + len)) };
    if (type === 'IEND') return;
    o += 12 + len;
  }
}

const TEXT_TYPES = new Set(['tEXt', 'iTXt', 'zTXt']);

/** The length of a text chunk's keyword (the 0 byte that ends it), looking at most 80 bytes far; -1 past that. */
const keywordLength = (c: Chunk): number => c.data.subarray(0, PNG_KEYWORD_BYTES + 1).indexOf(0);

const latin1 = (bytes: Uint8Array) => new TextDecoder('latin1').decode(bytes);

/**
 * The keyword of a text chunk (Latin-1 up to the first 0 byte). Only its first 80 bytes are looked
 * at: a keyword that is empty or longer than the specification allows is a PngProblem.
 */
function chunkKeyword(c: Chunk): string {
  const z = keywordLength(c);
  const at = `the ${c.type} chunk at byte ${c.start.toLocaleString('en')}`;
  if (z < 0)
    throw new PngProblem(`${at} has a keyword longer than ${PNG_KEYWORD_BYTES} bytes (the PNG limit)`);
  if (z === 0) throw new PngProblem(`${at} has an empty keyword`);
  return latin1(c.data.subarray(0, z));
}

/**
 * The tEXt and uncompressed iTXt entries of a PNG; null when the bytes are not a PNG. zTXt and
 * compressed iTXt are skipped: Kleinflow writes nothing compressed, so no inflation can explode.
 * With `only`, just that keyword's text is decoded. Throws PngProblem past `limits` (an entry's
 * size is checked before its text is decoded) or for a malformed keyword.
 */
export function readPngText(
  bytes: Uint8Array,
  limits: PngTextLimits = NO_LIMITS,
  only?: string,
): Record<string, string> | null {
  if (!isPng(bytes)) return null;
  const out: Record<string, string> = {};
  for (const c of chunks(bytes, limits.chunks)) {
    if (!TEXT_TYPES.has(c.type)) continue;
    const key = chunkKeyword(c);
    if (c.type === 'zTXt' || (only !== undefined && key !== only)) continue;
    let p = key.length + 1;
    if (c.type === 'iTXt') {
      if (c.data[p] !== 0) continue; // compressed
      // skip the compression flag and method, then the language tag and translated keyword (0-terminated)
      p = c.data.indexOf(0, p + 2) + 1;
      p = p > 0 ? c.data.indexOf(0, p) + 1 : 0;
      if (p === 0) continue;
    }
    const size = c.data.length - p;
    if (size > limits.textBytes)
      throw new PngProblem(
        `its "${key}" text is ${size.toLocaleString('en')} bytes, more than ${formatSize(limits.textBytes)}, the limit for it`,
      );
    out[key] = c.type === 'tEXt' ? latin1(c.data.subarray(p)) : new TextDecoder().decode(c.data.subarray(p));
  }
  return out;
}

const formatSize = (n: number) =>
  n >= 1 << 20 ? `${+(n / (1 << 20)).toFixed(1)} MB` : `${n.toLocaleString('en')} bytes`;

/**
 * A copy of a PNG with iTXt entries set: text chunks with the same keywords are removed and the
 * new entries go just before the first IDAT. Other chunks are copied byte for byte. Throws when
 * `bytes` is not a PNG (callers check with isPng first).
 */
export function setPngText(bytes: Uint8Array, text: Readonly<Record<string, string>>): Uint8Array {
  if (!isPng(bytes)) throw new Error('not a PNG file');
  const parts: Uint8Array[] = [bytes.subarray(0, 8)];
  const fresh = Object.entries(text).map(([k, t]) => itxt(k, t));
  let inserted = false;
  for (const c of chunks(bytes, Number.POSITIVE_INFINITY)) {
    if ((c.type === 'IDAT' || c.type === 'IEND') && !inserted) {
      parts.push(...fresh);
      inserted = true;
    }
    // A malformed keyword is no entry being set: that chunk is copied like any other.
    const z = TEXT_TYPES.has(c.type) ? keywordLength(c) : -1;
    if (!(z > 0 && Object.hasOwn(text, latin1(c.data.subarray(0, z)))))
      parts.push(bytes.subarray(c.start, c.end));
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

/**
 * Any PNG (every colour type, bit depth and interlacing, decoded by fast-png) as 8-bit RGBA.
 * Throws on a damaged file, with fast-png's reason.
 */
export function decodePng(bytes: Uint8Array): PngImage {
  const png = decode(bytes);
  const { width, height } = png;
  const values = png.palette ? convertIndexedToRgb(png) : png.data;
  const channels = png.palette ? png.palette[0].length : png.channels;
  const max = png.palette ? 255 : 2 ** png.depth - 1;
  if (values.length < width * height * channels)
    throw new Error('the PNG has fewer pixels than its size says');
  const out = new Uint8Array(width * height * 4);
  const to8 = max === 255 ? (v: number) => v : (v: number) => Math.round((v * 255) / max);
  const grey = channels < 3;
  const alpha = channels === 2 || channels === 4;
  for (let i = 0; i < width * height; i++) {
    const at = i * channels;
    out[i * 4] = to8(values[at]);
    out[i * 4 + 1] = to8(values[grey ? at : at + 1]);
    out[i * 4 + 2] = to8(values[grey ? at : at + 2]);
    out[i * 4 + 3] = alpha ? to8(values[at + channels - 1]) : 255;
  }
  return { width, height, data: out };
}
