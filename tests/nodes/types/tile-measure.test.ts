/** The tile's measure modes: final point, edge distance, escape speed and orbit trap, with the palette presets. */
import { describe, expect, it } from 'vitest';
import { isFieldShown } from '../../../nodes/core/field-visibility.ts';
import type { TileSpec } from '../../../nodes/core/tile-spec.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { defOf, evalNode } from '../support/eval-node.ts';

const tileOf = (params: Record<string, unknown>) => evalNode('tile', params).outputs?.tile as TileSpec;

describe('tile measure modes', () => {
  it('each mode colours by its measure through the chosen palette preset', () => {
    const cases = [
      ['final-point', { coordinate: 'radius' }, 'radius'],
      ['final-point', {}, 'argument'],
      ['edge-distance', {}, 'edge'],
      ['escape-speed', {}, 'speed'],
      ['orbit-trap', {}, 'trap'],
      ['formula', {}, 'formula'],
    ] as const;
    for (const [mode, extra, measure] of cases) {
      for (const [name, p] of Object.entries(PALETTES)) {
        const r = evalNode('tile', { mode, palette: name, scale: 2, offset: 0.25, ...extra });
        expect((r.outputs!.tile as TileSpec).coloring).toMatchObject({
          mode: 'measure',
          measure,
          a: p.a,
          d: p.d,
          scale: 2,
          offset: 0.25,
        });
        expect(r.readout).toContain(name);
      }
    }
  });

  it('the orbit trap is the trap centre and radius, drawn and draggable in the picture', () => {
    const params = { mode: 'orbit-trap', trapCenter: [0.5, -1], trapRadius: 0.3 };
    const coloring = tileOf(params).coloring;
    expect(coloring.mode === 'measure' && coloring.trap).toEqual({ c: [0.5, -1], r: 0.3 });
    const def = defOf('tile');
    const r = evalNode('tile', params);
    expect(def.handles!(r.ctx!, r.outputs!).map((h) => h.handle)).toEqual(['trap-center']);
    expect(def.overlay!(r.ctx!, r.outputs!)).toEqual([{ shape: 'circle', circle: { c: [0.5, -1], r: 0.3 } }]);
    expect(def.drag!('trap-center', [2, 3], r.ctx!)).toEqual({ trapCenter: [2, 3] });
  });

  it('shows the palette, scale and offset in the measure modes, the trap only for the trap', () => {
    const def = defOf('tile');
    for (const mode of ['final-point', 'edge-distance', 'escape-speed', 'orbit-trap', 'formula']) {
      expect(isFieldShown(def, 'palette', { mode })).toBe(true);
      expect(isFieldShown(def, 'scale', { mode })).toBe(true);
      expect(isFieldShown(def, 'trapCenter', { mode })).toBe(mode === 'orbit-trap');
      expect(isFieldShown(def, 'coordinate', { mode })).toBe(mode === 'final-point');
      expect(isFieldShown(def, 'formula', { mode })).toBe(mode === 'formula');
    }
    expect(isFieldShown(def, 'scale', { mode: 'cosine' })).toBe(false);
  });

  it('formula mode: the colour function travels with the colouring; a mistake is KF327 on the node', () => {
    const coloring = tileOf({ mode: 'formula', formula: 'n + length(z)' }).coloring;
    expect(coloring).toMatchObject({ mode: 'measure', measure: 'formula', formula: 'n + length(z)' });
    // the formula is only carried in formula mode
    expect(tileOf({ mode: 'escape-speed', formula: 'n' }).coloring).not.toHaveProperty('formula');
    const wrong = evalNode('tile', { mode: 'formula', formula: 'z * 2' });
    expect(wrong.diagnostics.map((d) => d.code)).toEqual(['KF327']);
    expect(wrong.diagnostics[0]!.message).toContain('a colour formula gives a number, not a point');
    expect(evalNode('tile', { mode: 'formula', formula: 'n +' }).diagnostics[0]!.code).toBe('KF327');
    // a mistake in the formula of another mode is no mistake (the field is hidden and unused)
    expect(evalNode('tile', { mode: 'cosine', formula: 'n +' }).diagnostics).toEqual([]);
  });
});
