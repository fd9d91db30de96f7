/**
 * Animated GIF writing (gifenc), shared by `kleinflow render --out x.gif` and the editor's
 * "Export animation…". Each frame gets its own 256-colour palette (quantized from that frame's
 * pixels, so smooth gradients survive); the file loops forever. Pure JS and deterministic: the
 * same frames give the same bytes.
 */
import * as gifenc from 'gifenc';

/** gifenc ships CommonJS to Node (everything under `default`) and ESM to bundlers: accept both. */
const lib: typeof gifenc =
  typeof (gifenc as { default?: { GIFEncoder?: unknown } }).default?.GIFEncoder === 'function'
    ? (gifenc as unknown as { default: typeof gifenc }).default
    : gifenc;

export interface GifFrame {
  readonly width: number;
  readonly height: number;
  /** RGBA, 8-bit, row 0 at the top. */
  readonly data: Uint8Array | Uint8ClampedArray;
}

export interface GifWriter {
  addFrame(frame: GifFrame): void;
  /** The finished file; the writer takes no more frames. */
  finish(): Uint8Array;
}

/**
 * A GIF at `fps` frames per second. GIF delays are whole centiseconds: the delay is the nearest
 * one (24 fps plays at 25), which is the format's limit, not a rounding of ours.
 */
export function gifWriter(fps: number): GifWriter {
  const encoder = lib.GIFEncoder();
  const delay = Math.max(10, Math.round(100 / fps) * 10);
  let frames = 0;
  return {
    addFrame({ width, height, data }) {
      const palette = lib.quantize(data, 256);
      const index = lib.applyPalette(data, palette);
      // repeat 0 = loop forever (written once, with the first frame).
      encoder.writeFrame(index, width, height, { palette, delay, repeat: 0 });
      frames++;
    },
    finish() {
      if (frames === 0) throw new Error('a GIF needs at least one frame');
      encoder.finish();
      return encoder.bytes();
    },
  };
}

/**
 * The image frames of GIF bytes, each as its raw bytes (image descriptor, local colour table and
 * compressed data): equal slices mean equal frames, so tests can tell frames apart without an LZW
 * decoder. Walks the block structure, skipping extensions.
 */
export function gifFrameBlocks(bytes: Uint8Array): Uint8Array[] {
  const header = String.fromCharCode(...bytes.subarray(0, 6));
  if (header !== 'GIF89a' && header !== 'GIF87a') throw new Error('not a GIF');
  let p = 13;
  const flags = bytes[10];
  if (flags & 0x80) p += 3 * (1 << ((flags & 7) + 1)); // global colour table
  const skipSubBlocks = () => {
    while (bytes[p] !== 0) p += bytes[p] + 1;
    p++;
  };
  const frames: Uint8Array[] = [];
  while (p < bytes.length) {
    const block = bytes[p++];
    if (block === 0x3b) return frames; // trailer
    if (block === 0x21) {
      p++; // extension label
      skipSubBlocks();
    } else if (block === 0x2c) {
      const start = p;
      const local = bytes[p + 8];
      p += 9;
      if (local & 0x80) p += 3 * (1 << ((local & 7) + 1));
      p++; // LZW minimum code size
      skipSubBlocks();
      frames.push(bytes.subarray(start, p));
    } else throw new Error(`bad GIF block 0x${block.toString(16)} at ${p - 1}`);
  }
  throw new Error('GIF ends without its trailer');
}

/** The number of image frames in GIF bytes. */
export const countGifFrames = (bytes: Uint8Array): number => gifFrameBlocks(bytes).length;
