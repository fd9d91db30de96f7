import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { openBytes } from '../../../src/io/document-io.ts';
import { decodePng, encodePng, readPngText } from '../../../src/io/png.ts';
import { embedGraph, extractGraph, PNG_GRAPH_KEY } from '../../../src/io/png-graph.ts';
import { exampleFiles } from './support/examples.ts';

const load = (text: string): GraphDoc => {
  const r = parseDocumentText(text, registry);
  if (!r.ok) throw new Error(r.diagnostics.map((d) => d.message).join('\n'));
  return r.doc;
};

/** A 3×2 image with distinct pixels, so pixel preservation is checked for real. */
const image = { width: 3, height: 2, data: Uint8Array.from({ length: 24 }, (_, i) => (i * 37) % 256) };

describe('graphs inside PNGs', () => {
  const [first, second] = exampleFiles().map((e) => load(e.text));

  it('embeds a graph in raw pixels and reads the same graph back', () => {
    const png = embedGraph(image, first);
    const r = extractGraph(png);
    expect(r.ok && r.doc).toEqual(first);
    expect(r.ok && r.source).toBe('png');
    expect([...decodePng(png).data]).toEqual([...image.data]);
  });

  it('adds a graph to an existing PNG, keeping its pixels and other text, replacing an older graph', () => {
    const original = encodePng(image, { Software: 'elsewhere' });
    const once = embedGraph(original, first);
    const twice = embedGraph(once, second);
    const text = readPngText(twice)!;
    expect(text.Software).toBe('elsewhere');
    expect(Object.keys(text).filter((k) => k === PNG_GRAPH_KEY)).toHaveLength(1);
    const r = extractGraph(twice);
    expect(r.ok && r.doc).toEqual(second);
    expect([...decodePng(twice).data]).toEqual([...image.data]);
  });

  it('opening a dropped Kleinflow PNG opens its graph', () => {
    const r = openBytes(embedGraph(image, first));
    expect(r.ok && r.doc).toEqual(first);
  });

  it('says so clearly when a PNG carries no graph, or the bytes are not a PNG', () => {
    const none = extractGraph(encodePng(image));
    expect(none.ok).toBe(false);
    if (!none.ok) expect(none.diagnostics[0].message).toMatch(/this PNG has no Kleinflow graph inside/);
    const notPng = extractGraph(new TextEncoder().encode('{"format":"kleinflow"}'));
    if (!notPng.ok) expect(notPng.diagnostics[0].message).toBe('this file is not a PNG image');
    expect(notPng.ok).toBe(false);
  });

  it('reports a damaged embedded graph with its paths', () => {
    const png = encodePng(image, {
      [PNG_GRAPH_KEY]:
        '{"format":"kleinflow","version":1,"meta":{},"nodes":[{}],"edges":[],"view":{"center":[0,0],"scale":1}}',
    });
    const r = extractGraph(png);
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.diagnostics.map((d) => d.path)).toContain('nodes[0].id');
  });
});
