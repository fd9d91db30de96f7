/**
 * The Render 3D node's volume mode (nodes/types/render-3d-volume.ts, docs/math-3d.md "§11 Volume
 * rendering of the nesting depth"): the scene carries a Volume3d only in volume mode, with the named
 * palette's a, b, c, d; out-of-range numbers are clamped with a message; its fields show only then,
 * and the sphere tracer's (colouring, environment, lighting, marching, reflections) only in surface
 * mode; it needs no seeds.
 */
import { describe, expect, it } from 'vitest';
import { isFieldShown } from '../../../nodes/core/field-visibility.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';
import { defOf } from '../support/eval-node.ts';

const evaluate = (params: Record<string, unknown>) => {
  const ev = evaluateGraph(doc([node('r', 'render-3d', params)]), registry);
  return { scene: ev.scene3d!, diagnostics: ev.nodes.get('r')!.diagnostics };
};

describe('Render 3D volume mode', () => {
  it('sets the volume only in volume mode, with the named palette', () => {
    expect(evaluate({}).scene.volume).toBeUndefined();
    const { scene } = evaluate({
      render: 'volume',
      volumePalette: 'dusk',
      volumeSteps: 80,
      density: 1.5,
      growth: 2,
      depthFrom: 2,
      depthTo: 6,
    });
    expect(scene.volume).toEqual({
      steps: 80,
      density: 1.5,
      growth: 2,
      depthFrom: 2,
      depthTo: 6,
      ...PALETTES.dusk,
    });
  });

  it('clamps out-of-range numbers with a message (never an error)', () => {
    const { scene, diagnostics } = evaluate({
      render: 'volume',
      volumeSteps: 1,
      density: -1,
      growth: 0,
      depthFrom: 0,
      depthTo: -3,
    });
    expect(scene.volume).toMatchObject({ steps: 4, density: 0, growth: 0.1, depthFrom: 1, depthTo: 1 });
    const clamped = diagnostics.filter((d) => / is outside /.test(d.message));
    expect(clamped.map((d) => d.message.split(' ')[0])).toEqual([
      'depthFrom',
      'volumeSteps',
      'density',
      'growth',
      'depthTo',
    ]);
    expect(diagnostics.every((d) => d.severity !== 'error')).toBe(true);
  });

  it('needs no seeds in volume mode (the surface mode says there is nothing to draw)', () => {
    const noSeeds = (render: string) =>
      evaluate({ render }).diagnostics.some((d) => /no seeds/.test(d.message));
    expect(noSeeds('surface')).toBe(true);
    expect(noSeeds('volume')).toBe(false);
  });

  it('shows the volume fields only in volume mode', () => {
    const def = defOf('render-3d');
    for (const field of ['volumeSteps', 'density', 'growth', 'depthFrom', 'depthTo', 'volumePalette']) {
      expect(isFieldShown(def, field, { render: 'volume' }), field).toBe(true);
      expect(isFieldShown(def, field, { render: 'surface' }), field).toBe(false);
    }
    expect(isFieldShown(def, 'render', {})).toBe(true);
  });

  it('hides the sphere tracer’s fields in volume mode, where they change nothing', () => {
    const def = defOf('render-3d');
    const surfaceOnly = ['coloring', 'environment', 'reflections', 'step', 'marchSteps', 'deScale'].concat([
      'light',
      'ambient',
      'diffuse',
      'specular',
      'shininess',
      'occlusion',
      'shadow',
    ]);
    for (const field of surfaceOnly) {
      expect(isFieldShown(def, field, { render: 'surface' }), field).toBe(true);
      expect(isFieldShown(def, field, { render: 'volume' }), field).toBe(false);
    }
    // what hangs on the colouring or the environment goes with it
    const palette = { coloring: 'cosine', palette: 'custom', environment: 'sky' };
    for (const field of ['palette', 'a', 'horizon', 'ground']) {
      expect(isFieldShown(def, field, { ...palette, render: 'surface' }), field).toBe(true);
      expect(isFieldShown(def, field, { ...palette, render: 'volume' }), field).toBe(false);
    }
    // what both modes use stays
    for (const field of ['camera', 'target', 'fov', 'maxIterations', 'samples', 'background'])
      expect(isFieldShown(def, field, { render: 'volume' }), field).toBe(true);
    // the switch itself comes first, so showing the colouring never moves it
    expect(Object.keys(def.params)[0]).toBe('render');
  });
});
