/**
 * The lost-edit bug: a node saved at an older version of its type, once loaded, must take the
 * user's edits. Node migrations run once, on load (and on paste); evaluation reads params as they are.
 */
import { describe, expect, it } from 'vitest';
import { emptyDocument } from '../../../nodes/graph/document.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { restore } from '../../../src/state/autosave.ts';
import { applyChange } from '../../../src/state/changes.ts';
import { copyNodes, parseClipboard, preparePaste, serializeClipboard } from '../../../src/state/clipboard.ts';
import { CURRENT_RING, ringRadius, ringRegistry, v1RingDoc } from '../../support/versioned-node.ts';

const editRadius = { type: 'set-params', patches: [{ nodeId: 'ring', params: { radius: 5 } }] } as const;

describe('an edit of a node saved at an older version', () => {
  it('changes the picture', () => {
    const loaded = parseDocumentText(JSON.stringify(v1RingDoc()), ringRegistry);
    if (!loaded.ok) throw new Error(loaded.diagnostics.map((d) => d.message).join('; '));
    expect(ringRadius(loaded.doc)).toBe(2);
    // The inspector writes the current key, as it does for every node.
    const edited = applyChange(loaded.doc, editRadius, ringRegistry);
    expect(ringRadius(edited)).toBe(5);
  });
});

describe('autosave restore migrates', () => {
  it('an autosaved old document comes back current, and edits show', () => {
    const text = JSON.stringify(v1RingDoc());
    const storage = { getItem: () => text, setItem: () => {}, removeItem: () => {} };
    const restored = restore(storage, ringRegistry);
    if (restored.kind !== 'ok') throw new Error(`not restored: ${restored.kind}`);
    expect(restored.doc.nodes[0]).toMatchObject(CURRENT_RING);
    expect(ringRadius(applyChange(restored.doc, editRadius, ringRegistry))).toBe(5);
  });
});

describe('a pasted fragment is migrated', () => {
  it('old nodes on the clipboard (another tab, an older Kleinflow) paste as current nodes', () => {
    const copied = copyNodes(v1RingDoc(), ['ring', 'inv']);
    if (!copied) throw new Error('nothing copied');
    const pasted = parseClipboard(serializeClipboard(copied), ringRegistry);
    expect(pasted?.nodes[0]).toMatchObject(CURRENT_RING);
    expect(pasted?.nodes[1]).toEqual(copied.nodes[1]); // the inversion was current already
    expect(pasted?.edges).toEqual(copied.edges);
  });

  it('a pasted old graph takes edits: the picture follows', () => {
    const copied = copyNodes(v1RingDoc(), ['ring', 'inv', 'out']);
    const data = copied && parseClipboard(serializeClipboard(copied), ringRegistry);
    if (!data) throw new Error('nothing to paste');
    const target = emptyDocument();
    const { nodes, edges } = preparePaste(target, data);
    const pasted = applyChange(target, { type: 'paste', nodes, edges }, ringRegistry);
    const ring = pasted.nodes.find((n) => n.type === 'test-ring')!;
    expect(ringRadius(pasted)).toBe(2);
    const edited = applyChange(
      pasted,
      { type: 'set-params', patches: [{ nodeId: ring.id, params: { radius: 5 } }] },
      ringRegistry,
    );
    expect(ringRadius(edited)).toBe(5);
  });

  it('unknown node types on the clipboard keep their data and version', () => {
    const text = serializeClipboard({
      format: 'kleinflow-clipboard',
      nodes: [{ id: 'u', type: 'from-the-future', version: 7, position: [0, 0], params: { r: 1 } }],
      edges: [],
    });
    expect(parseClipboard(text, ringRegistry)?.nodes[0]).toEqual({
      id: 'u',
      type: 'from-the-future',
      version: 7,
      position: [0, 0],
      params: { r: 1 },
    });
  });
});
