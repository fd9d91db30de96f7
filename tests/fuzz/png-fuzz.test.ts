/**
 * Fuzzing the PNG reader (fixed seeds): PNGs of random text and other chunks — keywords from empty
 * to far past the 79-byte limit, iTXt with any flags, truncated and oversized lengths — and the
 * pathological ones of issue #24 (a 2 MB keyword, a graph over 64 MB, more chunks than the limit).
 * Opening never throws: a graph, or problems each with a code, a place and one line of text.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { openBytes } from '../../src/io/document-io.ts';
import { INPUT_LIMITS } from '../../src/io/input-limits.ts';
import { embedGraph, PNG_GRAPH_KEY } from '../../src/io/png-graph.ts';
import { pngChunk, pngWith, textData } from '../src/io/support/png-chunks.ts';
import { readExamples } from './document-arbitraries.ts';

const SEED = 24;

const expectAnswered = (bytes: Uint8Array) => {
  const r = openBytes(bytes);
  if (r.ok) return 'ok';
  expect(r.diagnostics.length).toBeGreaterThan(0);
  for (const d of r.diagnostics) {
    expect(d.code).toMatch(/^KF\d{3}$/);
    expect(d.path ?? d.nodeId).toBeDefined();
    expect(d.message).not.toMatch(/\n/);
    expect(d.message.length).toBeLessThan(2_000);
  }
  return r.diagnostics[0].code;
};

const keyword = fc.oneof(
  fc.constantFrom(PNG_GRAPH_KEY, 'Software', ''),
  fc.string({ maxLength: 120 }).map((s) => s.replace(/\0/g, '')),
);
const textChunk = fc
  .record({
    type: fc.constantFrom('tEXt', 'iTXt', 'zTXt'),
    keyword,
    flags: fc.uint8Array({ minLength: 0, maxLength: 4 }),
    text: fc.string({ maxLength: 60 }),
  })
  .map(({ type, keyword: k, flags, text }) => {
    const key = Uint8Array.from(k, (c) => c.charCodeAt(0) & 0xff);
    const body = textData(key, text);
    if (type === 'tEXt') return pngChunk(type, body);
    const withFlags = new Uint8Array(body.length + flags.length);
    withFlags.set(body.subarray(0, key.length + 1));
    withFlags.set(flags, key.length + 1);
    withFlags.set(body.subarray(key.length + 1), key.length + 1 + flags.length);
    return pngChunk(type, withFlags);
  });
const otherChunk = fc
  .record({
    type: fc.constantFrom('tIME', 'pHYs', 'gAMA', 'IDAT', 'zzZz'),
    data: fc.uint8Array({ maxLength: 16 }),
  })
  .map(({ type, data }) => pngChunk(type, data));
/** A chunk whose length field lies (past the end of the file, or 0 with data after it). */
const lyingChunk = fc.record({ chunk: textChunk, length: fc.nat() }).map(({ chunk, length }) => {
  const out = chunk.slice();
  new DataView(out.buffer).setUint32(0, length);
  return out;
});

describe('PNG reader fuzzing', () => {
  it('random text and other chunks: opened or refused in one line, never thrown', () => {
    fc.assert(
      fc.property(
        fc.array(fc.oneof(textChunk, otherChunk, lyingChunk), { maxLength: 12 }),
        fc.nat(40),
        (chunks, cut) => {
          const png = pngWith(chunks);
          expectAnswered(png);
          expectAnswered(png.subarray(0, Math.max(8, png.length - cut)));
        },
      ),
      { seed: SEED, numRuns: 1_000 },
    );
  }, 60_000);

  it('the real graph among random chunks still opens', () => {
    const graph = readExamples()[0].doc as unknown as GraphDoc;
    fc.assert(
      fc.property(fc.array(fc.oneof(otherChunk, textChunk), { maxLength: 6 }), (chunks) => {
        const noKeywordProblem = chunks.every((c) => {
          const type = String.fromCharCode(c[4], c[5], c[6], c[7]);
          if (!['tEXt', 'iTXt', 'zTXt'].includes(type)) return true;
          const z = c.subarray(8, 8 + 80).indexOf(0);
          const key = new TextDecoder('latin1').decode(c.subarray(8, 8 + Math.max(z, 0)));
          return z > 0 && key !== PNG_GRAPH_KEY;
        });
        const code = expectAnswered(embedGraph(pngWith(chunks), graph));
        if (noKeywordProblem) expect(code).toBe('ok');
      }),
      { seed: SEED, numRuns: 200 },
    );
  }, 60_000);

  it('the pathological PNGs: a 2 MB keyword, a graph over the limit, too many chunks', () => {
    const longKeyword = new Uint8Array(2 * 1024 * 1024).fill(0x6b);
    expect(expectAnswered(pngWith([pngChunk('tEXt', textData(longKeyword, '{}'))]))).toBe('KF504');
    expect(expectAnswered(pngWith([pngChunk('iTXt', textData(longKeyword, ''))]))).toBe('KF504');
    const big = new Uint8Array(PNG_GRAPH_KEY.length + 1 + INPUT_LIMITS.documentBytes + 1).fill(0x20);
    big.set(textData(PNG_GRAPH_KEY, '').subarray(0, PNG_GRAPH_KEY.length + 1));
    expect(expectAnswered(pngWith([pngChunk('tEXt', big)]))).toBe('KF504');
    const tiny = pngChunk('tIME', new Uint8Array(7));
    expect(expectAnswered(pngWith(Array.from({ length: INPUT_LIMITS.pngChunks }, () => tiny)))).toBe('KF504');
  }, 60_000);
});
