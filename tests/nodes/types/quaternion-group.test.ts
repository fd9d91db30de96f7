/** The quaternion Kleinian group node (Fig. 6): its group, its refusals (KF303, KF340, KF341). */
import { describe, expect, it } from 'vitest';
import type { LimitSet3d } from '../../../nodes/core/limit-set-3d.ts';
import { pseudoDeterminant } from '../../../nodes/geometry/space/quaternion-mobius.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { parseQuaternionMatrices } from '../../../nodes/types/quaternion-group.ts';
import { doc, edge, node } from '../support/doc.ts';

const alone = (params: Record<string, unknown> = {}) => {
  const result = evaluateGraph(doc([node('n', 'quaternion-group', params)]), registry).nodes.get('n')!;
  return {
    ...result,
    group: result.outputs?.group as LimitSet3d | undefined,
    codes: result.diagnostics.map((d) => d.code),
    messages: result.diagnostics.map((d) => d.message),
  };
};

/** "A: …; B: …" from 8 quaternions. */
const typed = (...qs: number[][]) =>
  `A: ${qs
    .slice(0, 4)
    .map((q) => q.join(' '))
    .join(', ')}; B: ${qs
    .slice(4)
    .map((q) => q.join(' '))
    .join(', ')}`;
const ONE = [1, 0, 0, 0];
const ZERO = [0, 0, 0, 0];

describe('quaternion-group', () => {
  it('makes Sakugawa’s group by default, both generators with pseudo-determinant 1', () => {
    const r = alone();
    expect(r.codes).toEqual([]);
    expect(r.group?.nodeId).toBe('n');
    for (const g of r.group!.generators) expect(pseudoDeterminant(g)[0]).toBeCloseTo(1, 12);
    expect(r.group!.maxDepth).toBe(300);
  });

  it('types the default matrices out so that "matrices" starts from the same group', () => {
    const family = alone().group!.generators;
    const typedIn = alone({ family: 'matrices' }).group!.generators;
    for (const k of [0, 1])
      for (const e of ['a', 'b', 'c', 'd'] as const)
        for (let i = 0; i < 4; i++) expect(typedIn[k]![e][i]).toBeCloseTo(family[k]![e][i]!, 3);
  });

  it('refuses x outside −4 < x < 0', () => {
    expect(alone({ x: 0.5 }).messages).toEqual(['x = 0.5 is outside the family’s range −4 < x < 0']);
  });

  it('scales a typed matrix with a positive real pseudo-determinant to 1', () => {
    const r = alone({
      family: 'matrices',
      matrices: typed([2, 0, 0, 0], ZERO, ZERO, [2, 0, 0, 0], ONE, ONE, ZERO, ONE),
    });
    expect(r.codes).toEqual([]);
    expect(r.group!.generators[0].a[0]).toBeCloseTo(1, 12);
  });

  it('says which generator is singular (KF340) or not a Möbius transformation of space (KF341)', () => {
    const singular = alone({ family: 'matrices', matrices: typed(ONE, ZERO, ZERO, ONE, ONE, ONE, ONE, ONE) });
    expect(singular.codes).toEqual(['KF340']);
    expect(singular.messages[0]).toMatch(/^generator B is singular/);
    const offSpace = alone({
      family: 'matrices',
      matrices: typed(ONE, [0, 0, 0, 1], ZERO, ONE, ONE, ONE, ZERO, ONE),
    });
    expect(offSpace.codes).toEqual(['KF341']);
    expect(offSpace.messages[0]).toMatch(/^generator A is not a Möbius transformation of space/);
  });

  it('needs 32 numbers', () => {
    expect(parseQuaternionMatrices('A: 1 0 0 0')).toMatch(/needs 32 numbers .* it has 4/);
    expect(alone({ family: 'matrices', matrices: '1 2 3' }).codes).toEqual(['KF303']);
  });

  it('wired into Render 3D, becomes the scene’s limit set (and the render needs no seed)', () => {
    const e = evaluateGraph(
      doc([node('g', 'quaternion-group'), node('r', 'render-3d')], [edge('e', 'g.group', 'r.limitSets')]),
      registry,
    );
    expect(e.scene3d?.limitSets?.map((l) => l.nodeId)).toEqual(['g']);
    const render = e.nodes.get('r')!;
    expect(render.readout).toBe('0 elements, 0 seeds, 1 limit set');
    expect(render.diagnostics).toEqual([]);
  });
});
