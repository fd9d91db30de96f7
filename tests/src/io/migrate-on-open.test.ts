/**
 * Every way a document enters the app or the CLI migrates it once: a file's text, a dropped file's
 * bytes, a Kleinflow PNG, a share link (opened or pasted). The result is current (each node at its
 * type's version), so an edit of a renamed param shows in the picture.
 */
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { type OpenResult, openBytes, openDocumentText } from '../../../src/io/document-io.ts';
import { embedGraph, extractGraph } from '../../../src/io/png-graph.ts';
import { decodeShareFragment, encodeShareFragment } from '../../../src/io/share-url.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { CURRENT_RING, ringRadius, ringRegistry, v1RingDoc } from '../../support/versioned-node.ts';

const pixel = { width: 1, height: 1, data: new Uint8Array([0, 0, 0, 255]) };

function opened(result: OpenResult): GraphDoc {
  if (!result.ok) throw new Error(result.diagnostics.map((d) => d.message).join('; '));
  return result.doc;
}

function fragment(): string {
  const encoded = encodeShareFragment(v1RingDoc());
  if (!encoded.ok) throw new Error(encoded.message);
  return encoded.fragment;
}

function expectCurrentAndEditable(doc: GraphDoc) {
  expect(doc.nodes.find((n) => n.id === 'ring')).toMatchObject(CURRENT_RING);
  expect(ringRadius(doc)).toBe(2);
  const edited = applyChange(
    doc,
    { type: 'set-params', patches: [{ nodeId: 'ring', params: { radius: 5 } }] },
    ringRegistry,
  );
  expect(ringRadius(edited)).toBe(5);
}

const text = JSON.stringify(v1RingDoc());

describe('opening an older document migrates it once', () => {
  it('a file or pasted document (text)', () => {
    expectCurrentAndEditable(opened(openDocumentText(text, ringRegistry)));
  });

  it('a dropped file (bytes)', () => {
    expectCurrentAndEditable(opened(openBytes(new TextEncoder().encode(text), ringRegistry)));
  });

  it('a Kleinflow PNG, directly and as a dropped file', () => {
    const png = embedGraph(pixel, v1RingDoc());
    expectCurrentAndEditable(opened(extractGraph(png, ringRegistry)));
    expectCurrentAndEditable(opened(openBytes(png, ringRegistry)));
  });

  it('a share link, decoded and pasted', () => {
    const decoded = decodeShareFragment(fragment(), ringRegistry);
    if (!decoded.ok) throw new Error(decoded.message);
    expectCurrentAndEditable(decoded.doc);
    expectCurrentAndEditable(opened(openDocumentText(`https://example.org/${fragment()}`, ringRegistry)));
  });

  it('a second load of a current document changes nothing', () => {
    const once = opened(openDocumentText(text, ringRegistry));
    expect(opened(openDocumentText(JSON.stringify(once), ringRegistry))).toEqual(once);
  });

  it('an unknown node type is kept as it was, version and params included', () => {
    const placeholder = { id: 'u', type: 'from-the-future', version: 7, position: [1, 2], params: { r: 1 } };
    const withPlaceholder = { ...v1RingDoc(), nodes: [...v1RingDoc().nodes, placeholder] };
    const doc = opened(openDocumentText(JSON.stringify(withPlaceholder), ringRegistry));
    expect(doc.nodes.find((n) => n.id === 'u')).toEqual(placeholder);
  });
});
