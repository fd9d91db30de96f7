import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { scaleEdges } from '../../../../src/app/export.ts';
import { openReport } from '../../../../src/app/io/open-report.ts';
import { openPastedText } from '../../../../src/app/io/pasted-document.ts';
import { readStartupLink, shareLinkFor } from '../../../../src/app/io/share-link.ts';
import { openDocumentText } from '../../../../src/io/document-io.ts';
import { copyNodes, serializeClipboard } from '../../../../src/state/clipboard.ts';

const root = join(import.meta.dirname, '..', '..', '..', '..');
const text = readFileSync(join(root, 'examples', 'kaleidoscope-333.kleinflow.json'), 'utf8');
const doc = JSON.parse(text) as GraphDoc;
const where = { origin: 'https://kleinflow.example', pathname: '/app/' };

describe('pasted text', () => {
  it('opens a whole document and a share link, leaves copied nodes and prose to the editor', () => {
    const opened = openPastedText(text);
    expect(opened?.ok && opened.doc).toEqual(doc);
    const link = shareLinkFor(doc, where);
    expect(link.ok).toBe(true);
    const fromLink = openPastedText(link.ok ? link.url : '');
    expect(fromLink?.ok && fromLink.source).toBe('share-link');
    expect(openPastedText(serializeClipboard(copyNodes(doc, [doc.nodes[0].id])!))).toBeNull();
    expect(openPastedText('just some words')).toBeNull();
    expect(openPastedText('{"a": 1}')).toBeNull();
  });

  it('a broken document that is clearly meant as one is reported, not ignored', () => {
    const broken = openPastedText(JSON.stringify({ ...doc, nodes: [{ id: 3 }] }));
    expect(broken?.ok).toBe(false);
  });
});

describe('share link in the page', () => {
  it('is this page plus #g=, and reads back at startup; no fragment means nothing to do', () => {
    const link = shareLinkFor(doc, where);
    if (!link.ok) throw new Error(link.message);
    expect(link.url.startsWith('https://kleinflow.example/app/#g=')).toBe(true);
    const back = readStartupLink(link.url.slice(link.url.indexOf('#')));
    expect(back.kind === 'ok' && back.doc).toEqual(doc);
    expect(readStartupLink('').kind).toBe('none');
    expect(readStartupLink('#section-2').kind).toBe('none');
    const broken = readStartupLink('#g=%%%');
    expect(broken.kind).toBe('broken');
  });
});

describe('open report', () => {
  it('lists every problem with its path and says the graph is unchanged', () => {
    const result = openDocumentText(JSON.stringify({ ...doc, nodes: [{ id: 1 }, { id: 2 }] }));
    const report = openReport('“x.json”', result)!;
    expect(report.kind).toBe('error');
    expect(report.title).toContain('unchanged');
    expect(result.ok ? 0 : result.diagnostics.length).toBe(report.items.length);
    expect(report.items.every((i) => i.path.length > 0)).toBe(true);
    expect(report.items.some((i) => i.path.startsWith('nodes[0]'))).toBe(true);
    expect(report.items.every((i) => !i.text.startsWith(`${i.path}:`))).toBe(true);
  });

  it('says nothing after a clean open', () => {
    expect(openReport('x', openDocumentText(text))).toBeNull();
  });
});

describe('export edges', () => {
  it('widens pixel-sized tile edges by the export/view height ratio, and only those', () => {
    const scene = evaluateGraph(doc, registry).scene;
    const withEdges = { ...scene, tile: { ...scene.tile, edgeWidth: 1.5 } };
    expect(scaleEdges(withEdges, 8).tile.edgeWidth).toBe(12);
    expect(scaleEdges(withEdges, 8).elements).toBe(scene.elements);
    const none = { ...scene, tile: { ...scene.tile, edgeWidth: 0 } };
    expect(scaleEdges(none, 8)).toBe(none);
  });
});
