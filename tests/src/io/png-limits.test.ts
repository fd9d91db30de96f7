/**
 * The PNG limits (README "Limits"): a text keyword longer than the specification's 79 bytes, more
 * chunks than INPUT_LIMITS.pngChunks and an embedded graph over INPUT_LIMITS.documentBytes are
 * refused in one line (KF504), before any text is decoded, never with a crash.
 */
import { describe, expect, it } from 'vitest';
import { openBytes } from '../../../src/io/document-io.ts';
import { INPUT_LIMITS } from '../../../src/io/input-limits.ts';
import { PNG_GRAPH_KEY } from '../../../src/io/png-graph.ts';
import { pngChunk, pngWith, textData } from './support/png-chunks.ts';

const refusal = (bytes: Uint8Array) => {
  const r = openBytes(bytes);
  expect(r.ok).toBe(false);
  if (r.ok) return '';
  expect(r.diagnostics).toHaveLength(1);
  expect(r.diagnostics[0]).toMatchObject({ code: 'KF504', severity: 'error' });
  expect(r.diagnostics[0].message).not.toMatch(/\n/);
  return r.diagnostics[0].message;
};

describe('PNG limits', () => {
  it('a text keyword of 2 MB is refused (keywords are at most 79 bytes), not a stack overflow', () => {
    const keyword = new Uint8Array(2 * 1024 * 1024).fill(0x41);
    const message = refusal(pngWith([pngChunk('tEXt', textData(keyword, 'x'))]));
    expect(message).toMatch(/keyword .*longer than 79 bytes/);
  });

  it('an embedded graph over the graph limit is refused before its text is decoded', () => {
    const big = INPUT_LIMITS.documentBytes + 1;
    const data = new Uint8Array(PNG_GRAPH_KEY.length + 5 + big).fill(0x20);
    data.set(textData(PNG_GRAPH_KEY, '').subarray(0, PNG_GRAPH_KEY.length + 1));
    data.fill(0, PNG_GRAPH_KEY.length, PNG_GRAPH_KEY.length + 5);
    const decode = TextDecoder.prototype.decode;
    let decoded = 0;
    TextDecoder.prototype.decode = function (this: TextDecoder, ...args) {
      decoded += (args[0] as Uint8Array | undefined)?.byteLength ?? 0;
      return decode.apply(this, args);
    };
    try {
      const message = refusal(pngWith([pngChunk('iTXt', data)]));
      expect(message).toMatch(/"kleinflow" text is 67,108,865 bytes, more than 64 MB/);
    } finally {
      TextDecoder.prototype.decode = decode;
    }
    expect(decoded).toBeLessThan(1024);
  });

  it('a PNG of more chunks than the limit is refused, quickly', () => {
    const tiny = pngChunk('tIME', new Uint8Array(7));
    const many = pngWith(Array.from({ length: INPUT_LIMITS.pngChunks + 1 }, () => tiny));
    const start = performance.now();
    expect(refusal(many)).toMatch(
      new RegExp(`more than ${INPUT_LIMITS.pngChunks.toLocaleString('en')} chunks`),
    );
    expect(performance.now() - start).toBeLessThan(2000);
  });

  it('a graph just under the limits still opens', () => {
    const ok = pngWith([pngChunk('tEXt', textData('k'.repeat(79), 'fine'))]);
    const r = openBytes(ok);
    // No graph inside, but no limit problem either (KF501, not KF504).
    expect(r.ok || r.diagnostics[0].code).toBe('KF501');
  });
});
