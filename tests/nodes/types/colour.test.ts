import { describe, expect, it } from 'vitest';
import { DEFAULT_TILE } from '../../../nodes/core/scene.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';
import { checkDefaults, codes, evalNode } from '../support/eval-node.ts';

describe('colour nodes', () => {
  it('color outputs the picked colour', () => {
    expect(checkDefaults('color').readout).toBe('#e85d75');
    expect(evalNode('color', { color: '#ff0000' }).outputs!.color).toEqual([1, 0, 0]);
    expect(codes(evalNode('color', { color: 'red' }))).toEqual(['KF301']);
  });

  it('cosine-palette: presets, or the a, b, c, d inputs when custom', () => {
    const r = checkDefaults('cosine-palette');
    const def = DEFAULT_TILE.coloring;
    if (def.mode === 'cosine') expect(r.outputs!.d).toEqual(def.d);
    expect(evalNode('cosine-palette', { preset: 'ember' }).outputs!.c).toEqual(PALETTES.ember.c);
    const custom = evalNode('cosine-palette', { preset: 'custom', a: '#000000' });
    expect(custom.outputs!.a).toEqual([0, 0, 0]);
  });

  it('wires into the tile node', () => {
    const g = doc(
      [node('p', 'cosine-palette', { preset: 'warm' }), node('t', 'tile')],
      [
        edge('e1', 'p.a', 't.a'),
        edge('e2', 'p.b', 't.b'),
        edge('e3', 'p.c', 't.c'),
        edge('e4', 'p.d', 't.d'),
      ],
    );
    const tile = evaluateGraph(g, registry).nodes.get('t')!.outputs!.tile as { coloring: { d: number[] } };
    expect(tile.coloring.d).toEqual([0, 0.1, 0.2]);
  });
});
