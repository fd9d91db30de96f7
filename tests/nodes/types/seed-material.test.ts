/**
 * Seed materials and the Render 3D node's reflection settings (docs/math-3d.md "Mirror material"):
 * a mirror seed carries its reflectivity (clamped into 0…1 with a KF402 warning), a matte one none;
 * the reflections are clamped to 0…4 whole bounces; the environment is flat unless sky is chosen.
 */
import { describe, expect, it } from 'vitest';
import { isFieldShown } from '../../../nodes/core/field-visibility.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, node } from '../support/doc.ts';
import { defOf } from '../support/eval-node.ts';

const alone = (type: string, params: Record<string, unknown> = {}) => {
  const result = evaluateGraph(doc([node('n', type, params)]), registry).nodes.get('n')!;
  return { ...result, messages: result.diagnostics.map((d) => `${d.code} ${d.message}`) };
};

describe('seed material', () => {
  it('a mirror seed sphere, box or solid carries its reflectivity; a matte one has none', () => {
    for (const type of ['seed-sphere', 'seed-box', 'seed-solid']) {
      const mirror = alone(type, { material: 'mirror', reflectivity: 0.7 });
      expect(mirror.outputs?.seed, type).toMatchObject({ reflectivity: 0.7 });
      expect(mirror.messages, type).toEqual([]);
      const matte = alone(type, { reflectivity: 0.7 });
      expect(matte.outputs?.seed, type).not.toHaveProperty('reflectivity');
    }
  });

  it('clamps a reflectivity outside 0…1 with a warning on the node', () => {
    const r = alone('seed-sphere', { material: 'mirror', reflectivity: 1.5 });
    expect(r.outputs?.seed).toMatchObject({ reflectivity: 1 });
    expect(r.messages).toEqual(['KF402 reflectivity 1.5 is outside 0…1: 1 is used']);
  });

  it('shows the reflectivity only for a mirror', () => {
    const def = defOf('seed-sphere');
    expect(isFieldShown(def, 'reflectivity', { material: 'matte' })).toBe(false);
    expect(isFieldShown(def, 'reflectivity', { material: 'mirror' })).toBe(true);
  });
});

describe('Render 3D reflections and environment', () => {
  const scene = (params: Record<string, unknown>) => {
    const ev = evaluateGraph(doc([node('r', 'render-3d', params)]), registry);
    return {
      scene: ev.scene3d!,
      messages: ev.nodes.get('r')!.diagnostics.map((d) => `${d.code} ${d.message}`),
    };
  };

  it('defaults to two reflections and the flat background', () => {
    const { scene: s } = scene({});
    expect(s.reflections).toBe(2);
    expect(s.environment).toEqual({ mode: 'flat' });
  });

  it('clamps the reflections to 0…4 whole bounces', () => {
    const { scene: s, messages } = scene({ reflections: 7 });
    expect(s.reflections).toBe(4);
    expect(messages).toContain('KF402 reflections 7 is outside 0…4 (whole numbers): 4 is used');
  });

  it('a sky carries its horizon and ground colours', () => {
    const { scene: s } = scene({ environment: 'sky', horizon: '#ff0000', ground: '#0000ff' });
    expect(s.environment).toEqual({ mode: 'sky', horizon: [1, 0, 0], ground: [0, 0, 1] });
  });
});
