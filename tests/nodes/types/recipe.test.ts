/** The recipe node: what it outputs and what it says about drawing the group. */
import { describe, expect, it } from 'vitest';
import type { SceneElement } from '../../../nodes/core/scene-elements.ts';
import { codes, evalNode } from '../support/eval-node.ts';

const elementsOf = (params: Record<string, unknown>) =>
  evalNode('recipe', params).outputs?.elements as SceneElement[];

describe('recipe node', () => {
  it('two loxodromic generators: the Ford rule on their isometric circles, with a warning that says so', () => {
    const params = { ta_re: 1.91, ta_im: 0.05, tb_re: 1.91, tb_im: -0.05 };
    for (const recipe of ['grandma', 'jorgensen']) {
      const r = evalNode('recipe', { ...params, recipe });
      expect((r.outputs!.elements as SceneElement[]).map((e) => e.kind)).toEqual([
        'mobius-matrix',
        'mobius-matrix',
      ]);
      expect(codes(r, 'warning')).toEqual(['KF304']);
      const message = r.diagnostics[0].message;
      expect(message).toContain('loxodromic');
      expect(message).toContain('IIS cannot draw');
      expect(message).toContain('overlap here');
      expect(r.readout).toMatch(/^a = \[\[.*tr ab = /);
    }
  });

  it('one parabolic generator (tb = 2): the exact Maskit limit set, μ = i·ta, and an info note', () => {
    const r = evalNode('recipe', { recipe: 'grandma', ta_re: 1.8, ta_im: -0.4, tb_re: 2, tb_im: 0 });
    const [e] = r.outputs!.elements as SceneElement[];
    expect(e.kind).toBe('maskit');
    if (e.kind === 'maskit') {
      expect(e.mu[0]).toBeCloseTo(0.4, 9);
      expect(e.mu[1]).toBeCloseTo(1.8, 9);
    }
    expect(r.diagnostics.map((d) => [d.code, d.severity])).toEqual([['KF315', 'info']]);
    expect(r.diagnostics[0].message).toContain('Maskit');
  });

  it('the defaults (ta = tb = 2) are the Apollonian gasket group, μ = 2i', () => {
    const [e] = elementsOf({});
    expect(e.kind === 'maskit' && e.mu.map((x) => Number(x.toFixed(9)))).toEqual([0, 2]);
  });

  it('Riley’s recipe: a on its tangent isometric circles and b = z + 2 as a translation strip', () => {
    const wide = evalNode('recipe', { recipe: 'riley', c_re: 0.3, c_im: 0.5 });
    expect(codes(wide, 'warning')).toEqual(['KF304']); // radius 1/|c| ≈ 1.7: they overlap their translates
    const r = evalNode('recipe', { recipe: 'riley', c_re: 0, c_im: 2 });
    const els = r.outputs?.elements as SceneElement[];
    expect(els.map((e) => e.kind)).toEqual(['mobius-matrix', 'translation']);
    const strip = els[1];
    if (strip.kind === 'translation') {
      expect(strip.period).toBeCloseTo(2, 12);
      expect(strip.n).toEqual([1, 0]);
      expect(strip.q).toEqual([-1, -0]);
    }
    // |c| = 2: a's isometric circles (radius ½, tangent at 0) and their translates are disjoint
    // or tangent, so the Ford rule is exact and the node only notes it.
    expect(r.diagnostics.map((d) => [d.code, d.severity])).toEqual([['KF315', 'info']]);
    expect(r.diagnostics[0].message).toContain('exact');
  });

  it('a recipe that divides by zero is an error on the node, not a broken picture', () => {
    // Jørgensen needs tab ≠ 0: ta = tb = 0 gives tab = 0.
    const r = evalNode('recipe', { recipe: 'jorgensen', ta_re: 0, ta_im: 0, tb_re: 0, tb_im: 0 });
    expect(codes(r)).toEqual(['KF303']);
  });
});
