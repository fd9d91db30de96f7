import { describe, expect, it } from 'vitest';
import { GENERATOR_COLOURS } from '../../../shader-gen/figures/layer.ts';
import { exportSvg } from '../../../shader-gen/vector/index.ts';
import { hexColour } from '../../../shader-gen/vector/svg.ts';
import { loadExample } from '../../support/examples.ts';
import { parseXml } from '../../support/xml.ts';

const SIZE = { width: 400, height: 400, minRadius: 2 };

describe('SVG export of the figures', () => {
  it('writes the Cayley graph over the tiling: one coloured polyline per edge, labels a–d', () => {
    const { scene } = loadExample('fig01-cayley-graph');
    const r = exportSvg(scene, SIZE);
    if (!r.ok) throw new Error(r.message);
    const doc = parseXml(r.svg);
    const figures = doc.querySelector('g.figures');
    expect(figures).not.toBeNull();
    const lines = [...(figures?.querySelectorAll('polyline') ?? [])];
    const colours = new Set(lines.map((l) => l.getAttribute('stroke')));
    expect(colours).toEqual(new Set(GENERATOR_COLOURS.slice(0, 4).map(hexColour)));
    const labels = [...(figures?.querySelectorAll('text') ?? [])].map((t) => t.textContent).sort();
    expect(labels).toEqual(['a', 'b', 'c', 'd']);
    expect(r.edgeCount).toBeGreaterThan(100);
    expect(r.figureCount).toBe(lines.length + (figures?.querySelectorAll('circle').length ?? 0));
  });

  it('writes the depth-first limit set of a group of matrix generators, leaving out the tiling with a note', () => {
    const { scene } = loadExample('schottky-matrix-generators');
    expect(exportSvg(scene, SIZE).ok).toBe(false);
    const r = exportSvg({ ...scene, figures: { cayleyDepth: 0, cayleyBase: null, limitSetDfs: true } }, SIZE);
    if (!r.ok) throw new Error(r.message);
    expect(r.edgeCount).toBe(0);
    expect(r.figureCount).toBeGreaterThan(20);
    expect(r.notes.join(' ')).toMatch(/the tiling is left out: node .* Möbius matrix generator/);
  });
});
