/** The tile's palette presets: one choice sets all four cosine colours; "custom" keeps a, b, c, d. */
import { describe, expect, it } from 'vitest';
import { isFieldShown } from '../../../nodes/core/field-visibility.ts';
import type { TileSpec } from '../../../nodes/core/tile-spec.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { defOf, evalNode } from '../support/eval-node.ts';

const tileOf = (params: Record<string, unknown>) => evalNode('tile', params).outputs?.tile as TileSpec;

describe('tile palette presets', () => {
  it('a named preset replaces a, b, c, d, and the node says which', () => {
    for (const [name, p] of Object.entries(PALETTES)) {
      const r = evalNode('tile', { palette: name, a: '#ff0000' });
      const tile = r.outputs?.tile as TileSpec | undefined;
      expect(tile?.coloring).toMatchObject({ mode: 'cosine', a: p.a, b: p.b, c: p.c, d: p.d });
      expect(r.readout).toBe(`cosine · ${name}`);
    }
  });

  it('"custom" (and a document from before presets, without the param) uses the a, b, c, d inputs', () => {
    for (const params of [{ palette: 'custom', a: '#ff0000' }, { a: '#ff0000' }]) {
      const coloring = tileOf(params).coloring;
      expect(coloring.mode === 'cosine' && coloring.a).toEqual([1, 0, 0]);
    }
  });

  it('shows the four colours only for "custom", and the palette only in cosine mode', () => {
    const def = defOf('tile');
    expect(isFieldShown(def, 'palette', { mode: 'cosine' })).toBe(true);
    expect(isFieldShown(def, 'palette', { mode: 'parity' })).toBe(false);
    expect(isFieldShown(def, 'a', { mode: 'cosine', palette: 'custom' })).toBe(true);
    expect(isFieldShown(def, 'a', { mode: 'cosine', palette: 'dusk' })).toBe(false);
    expect(isFieldShown(def, 'a', { mode: 'parity', palette: 'custom' })).toBe(false);
    // A wired colour input stays in sight whatever the palette.
    expect(isFieldShown(def, 'a', { mode: 'cosine', palette: 'dusk' }, new Set(['a']))).toBe(true);
  });
});
