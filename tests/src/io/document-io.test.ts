import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { openBytes, openDocumentText, serializeDocument } from '../../../src/io/document-io.ts';
import { encodeShareFragment } from '../../../src/io/share-url.ts';
import { exampleFiles } from './support/examples.ts';

const load = (text: string): GraphDoc => {
  const r = parseDocumentText(text, registry);
  if (!r.ok) throw new Error(r.diagnostics.map((d) => d.message).join('\n'));
  return r.doc;
};

/** A graph with a node type this Kleinflow does not know, wired to known nodes both ways. */
const WITH_UNKNOWN = {
  format: 'kleinflow',
  version: 1,
  meta: { title: 'From the future', author: 'someone', tags: ['a', 'b'] },
  nodes: [
    { id: 'p', type: 'point', position: [0, 0], params: { x: 0.5, y: -0.25 } },
    {
      id: 'w',
      type: 'warp-field',
      version: 3,
      label: 'Warp',
      position: [200, 0],
      params: {
        strength: 2.5,
        mode: 'swirl',
        curve: [
          [0, 1],
          [1, 0],
        ],
        nested: { deep: { ok: true } },
      },
    },
    { id: 'r', type: 'render', position: [400, 0], params: {} },
  ],
  edges: [
    { id: 'e1', from: { node: 'p', port: 'point' }, to: { node: 'w', port: 'centre' } },
    { id: 'e2', from: { node: 'w', port: 'elements' }, to: { node: 'r', port: 'elements' } },
  ],
  view: { center: [0.1, -0.2], scale: 3.5 },
};

describe('serializeDocument', () => {
  const examples = exampleFiles();
  for (const { name, text } of examples) {
    it(`${name}: load → serialize → load is lossless and serialize is idempotent`, () => {
      const doc = load(text);
      const saved = serializeDocument(doc);
      const again = load(saved);
      expect(again).toEqual(doc);
      expect(serializeDocument(again)).toBe(saved);
    });
  }

  it('writes 2-space indentation, a trailing newline and a fixed key order', () => {
    const doc = load(JSON.stringify(WITH_UNKNOWN));
    const text = serializeDocument(doc);
    expect(text.endsWith('}\n')).toBe(true);
    expect(text.split('\n')[1]).toBe('  "format": "kleinflow",');
    const top = [...text.matchAll(/^ {2}"(\w+)":/gm)].map((m) => m[1]);
    expect(top).toEqual(['format', 'version', 'meta', 'nodes', 'edges', 'view']);
    // The same document with keys in another order saves to the same bytes.
    const shuffled = JSON.parse(JSON.stringify(WITH_UNKNOWN), (_k, v) =>
      v && typeof v === 'object' && !Array.isArray(v) ? Object.fromEntries(Object.entries(v).reverse()) : v,
    );
    expect(serializeDocument(load(JSON.stringify(shuffled)))).toBe(text);
  });

  it('keeps a node of an unknown type and its edges unchanged through load → serialize → load', () => {
    const doc = load(JSON.stringify(WITH_UNKNOWN));
    expect(doc).toEqual(WITH_UNKNOWN);
    const again = load(serializeDocument(doc));
    expect(again).toEqual(WITH_UNKNOWN);
    const analysis = evaluateGraph(again, registry);
    expect(analysis.diagnostics.map((d) => d.code)).toContain('KF203');
  });
});

describe('openDocumentText', () => {
  it('opens a Kleinflow document', () => {
    const r = openDocumentText(exampleFiles()[0].text);
    expect(r.ok && r.source).toBe('kleinflow');
  });

  it('recognises a Flower graph by its shape and imports it', () => {
    const flower = {
      nodes: [
        {
          name: 'Point',
          x: 0,
          y: 0,
          id: 'p',
          sockets: [
            { id: 's1', name: 'Float', isOutput: false },
            { id: 's2', name: 'Float', isOutput: false },
            { id: 's3', name: 'Point', isOutput: true },
          ],
          posX: 1,
          posY: 2,
        },
      ],
      edges: [],
    };
    const r = openDocumentText(JSON.stringify(flower));
    expect(r.ok).toBe(true);
    if (r.ok) {
      expect(r.source).toBe('flower');
      expect(r.doc.nodes.find((n) => n.type === 'point')?.params).toEqual({ x: 1, y: 2 });
    }
  });

  it('opens a pasted share link', () => {
    const doc = load(exampleFiles()[0].text);
    const link = encodeShareFragment(doc);
    if (!link.ok) throw new Error(link.message);
    const r = openDocumentText(`https://example.org/kleinflow/${link.fragment}`);
    expect(r.ok && r.source).toBe('share-link');
    expect(r.ok && r.doc).toEqual(doc);
  });

  it('reports every problem with its path', () => {
    const bad = {
      ...WITH_UNKNOWN,
      nodes: [
        { id: '', type: 'point', position: [0, 0], params: {} },
        { id: 'q', type: 'point', position: [0, Number.NaN], params: {} },
      ],
      view: { center: [0, 0], scale: -1 },
    };
    const r = openDocumentText(JSON.stringify(bad).replace('null', '"x"'));
    expect(r.ok).toBe(false);
    if (r.ok) return;
    const paths = r.diagnostics.map((d) => d.path);
    expect(paths).toEqual(expect.arrayContaining(['nodes[0].id', 'nodes[1].position[1]', 'view.scale']));
    for (const d of r.diagnostics) expect(d.message).toContain(d.path!);
  });

  it('says clearly what is wrong with text that is not a graph', () => {
    const codes = (text: string) => {
      const r = openDocumentText(text);
      return r.ok ? [] : r.diagnostics.map((d) => `${d.code} ${d.message}`);
    };
    expect(codes('')[0]).toMatch(/KF501 the file is empty/);
    expect(codes('{ "nodes": [')[0]).toMatch(/^KF101 not valid JSON/);
    expect(codes('{ "format": "other" }')[0]).toMatch(/^KF103/);
    expect(codes('[1, 2]')[0]).toMatch(/expected a JSON object, got an array/);
    expect(codes('#g=@@@')[0]).toMatch(/share link is damaged/);
  });
});

describe('openBytes', () => {
  it('opens UTF-8 JSON (with a byte-order mark) like text', () => {
    const text = `\uFEFF${exampleFiles()[0].text}`;
    const r = openBytes(new TextEncoder().encode(text));
    expect(r.ok && r.source).toBe('kleinflow');
  });

  it('refuses binary that is neither JSON nor PNG with a message', () => {
    const r = openBytes(Uint8Array.from([0xff, 0xfe, 0x00, 0x81, 0x90]));
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.diagnostics[0].message).toMatch(/neither a Kleinflow graph/);
  });
});
