/**
 * The Render 3D node's colourings: palette presets (a named cosine palette, the colour wheel, or
 * custom a, b, c, d) for the depth palette and the measured colourings by distance and argument
 * (docs/math-3d.md §9 "Colour").
 */
import { describe, expect, it } from 'vitest';
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import { isFieldShown } from '../../../nodes/core/field-visibility.ts';
import type { Coloring3d } from '../../../nodes/core/scene-3d.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';
import { defOf } from '../support/eval-node.ts';

const coloringOf = (
  params: Record<string, unknown>,
): { coloring: Coloring3d; diagnostics: readonly Diagnostic[] } => {
  const ev = evaluateGraph(doc([node('r', 'render-3d', params)]), registry);
  return { coloring: ev.scene3d!.coloring, diagnostics: ev.nodes.get('r')!.diagnostics };
};

describe('Render 3D colourings', () => {
  it('a named palette replaces a, b, c, d in every palette mode', () => {
    for (const [name, p] of Object.entries(PALETTES))
      for (const coloring of ['cosine', 'distance', 'argument'])
        expect(coloringOf({ coloring, palette: name, a: '#ff0000' }).coloring).toMatchObject({
          mode: coloring,
          a: p.a,
          b: p.b,
          c: p.c,
          d: p.d,
        });
  });

  it('"custom" (and a document from before presets) keeps the a, b, c, d inputs', () => {
    for (const params of [
      { coloring: 'cosine', palette: 'custom', a: '#ff0000' },
      { coloring: 'cosine', a: '#ff0000' },
    ])
      expect(coloringOf(params).coloring).toMatchObject({ mode: 'cosine', a: [1, 0, 0], step: 0.1 });
  });

  it('the wheel by depth is the depth wheel; by a measure it is flagged', () => {
    expect(coloringOf({ coloring: 'cosine', palette: 'wheel', step: 0.3 }).coloring).toEqual({
      mode: 'depth-wheel',
      step: 0.3,
    });
    expect(coloringOf({ coloring: 'argument', palette: 'wheel' }).coloring).toMatchObject({ wheel: true });
    expect(coloringOf({ coloring: 'argument', palette: 'dusk' }).coloring).toMatchObject({ wheel: false });
  });

  it('distance takes 1/scale palette steps per unit, argument `cycles` per turn, both from the offset', () => {
    expect(coloringOf({ coloring: 'distance', scale: 0.5, offset: 0.25 }).coloring).toMatchObject({
      mode: 'distance',
      frequency: 2,
      offset: 0.25,
    });
    expect(coloringOf({ coloring: 'argument', cycles: 3, scale: 0.5 }).coloring).toMatchObject({
      mode: 'argument',
      frequency: 3,
      offset: 0,
    });
  });

  it('a scale that is not positive is replaced by 1, with a message on the scale', () => {
    const { coloring, diagnostics } = coloringOf({ coloring: 'distance', scale: 0 });
    expect(coloring).toMatchObject({ frequency: 1 });
    expect(diagnostics.some((d) => d.port === 'scale' && d.severity !== 'error')).toBe(true);
  });

  it('shows the palette in the palette modes, its colours only for "custom", each measure its own control', () => {
    const def = defOf('render-3d');
    for (const coloring of ['cosine', 'distance', 'argument'])
      expect(isFieldShown(def, 'palette', { coloring })).toBe(true);
    for (const coloring of ['depth-wheel', 'surface', 'final-point'])
      expect(isFieldShown(def, 'palette', { coloring })).toBe(false);
    expect(isFieldShown(def, 'a', { coloring: 'distance', palette: 'custom' })).toBe(true);
    expect(isFieldShown(def, 'a', { coloring: 'distance', palette: 'warm' })).toBe(false);
    expect(isFieldShown(def, 'a', { coloring: 'surface', palette: 'custom' })).toBe(false);
    expect(isFieldShown(def, 'scale', { coloring: 'distance' })).toBe(true);
    expect(isFieldShown(def, 'cycles', { coloring: 'distance' })).toBe(false);
    expect(isFieldShown(def, 'cycles', { coloring: 'argument' })).toBe(true);
    expect(isFieldShown(def, 'offset', { coloring: 'argument' })).toBe(true);
    expect(isFieldShown(def, 'offset', { coloring: 'cosine' })).toBe(false);
  });

  it('formula: the colour function travels with the colouring; a mistake is KF327 on the node', () => {
    const { coloring } = coloringOf({ coloring: 'formula', formula: 'n + z', palette: 'dusk', offset: 0.5 });
    expect(coloring).toMatchObject({
      mode: 'formula',
      formula: 'n + z',
      frequency: 1,
      offset: 0.5,
      a: PALETTES.dusk!.a,
    });
    const def = defOf('render-3d');
    expect(isFieldShown(def, 'formula', { coloring: 'formula' })).toBe(true);
    expect(isFieldShown(def, 'formula', { coloring: 'distance' })).toBe(false);
    expect(isFieldShown(def, 'palette', { coloring: 'formula' })).toBe(true);
    const ev = evaluateGraph(
      doc([node('r', 'render-3d', { coloring: 'formula', formula: 'point(x, y)' })]),
      registry,
    );
    const [problem] = ev.nodes.get('r')!.diagnostics;
    expect(problem).toMatchObject({ code: 'KF327', severity: 'error' });
    expect(problem!.message).toContain('a colour formula gives a number, not a point');
    // a mistake in the formula of another colouring is no mistake (the field is hidden and unused)
    expect(coloringOf({ coloring: 'cosine', formula: 'n +' }).diagnostics.map((x) => x.code)).not.toContain(
      'KF327',
    );
  });
});
