import { describe, expect, it } from 'vitest';
import { tileNode } from '../../../nodes/types/tile.ts';
import { estimateSize } from '../../../src/editor/layout.ts';
import { nodeFields } from '../../../src/editor/node-fields.ts';

const names = (fs: readonly { name: string }[]) => fs.map((f) => f.name);
const none = new Set<string>();

describe("a node's rows", () => {
  it('puts the switches first, then the fields of the chosen mode, rare ones under More', () => {
    const { main, more } = nodeFields(tileNode, { mode: 'parity' }, none);
    expect(names(main)).toEqual(['mode', 'fillTile', 'even', 'odd', 'seeds', 'inner']);
    expect(names(more)).toEqual(['limit', 'background', 'edgeColor', 'seedsOnly', 'seedFade', 'edgeWidth']);
  });

  it('keeps a wired input in the main list even when its mode hides it', () => {
    const wired = new Set(['a', 'edgeColor']);
    const { main, more } = nodeFields(tileNode, { mode: 'limit-set' }, wired);
    expect(names(main)).toEqual(['mode', 'a', 'limit', 'background', 'edgeColor', 'seeds', 'glow']);
    expect(names(more)).toEqual(['seedsOnly', 'seedFade']);
  });

  it('shows a field with a problem of its own whatever the mode', () => {
    const { main } = nodeFields(
      tileNode,
      { mode: 'cosine', imageSize: -1 },
      none,
      new Set(['imageSize', 'edgeWidth']),
    );
    expect(names(main)).toContain('imageSize');
    expect(names(main)).toContain('edgeWidth');
  });

  it('sizes the node for what it shows', () => {
    const tile = (mode: string) =>
      estimateSize({ id: 't', type: 'tile', position: [0, 0], params: { mode } }, tileNode, none).height;
    expect(tile('limit-set')).toBeLessThan(tile('parity'));
    expect(tile('parity')).toBeLessThan(tile('cosine'));
  });
});
