import { describe, expect, it } from 'vitest';
import { registry } from '../../../nodes/types/index.ts';
import { compatiblePort, fuzzyScore, searchNodeTypes } from '../../../src/editor/fuzzy.ts';

describe('palette search', () => {
  it('matches characters in order, and prefers word starts', () => {
    expect(fuzzyScore('pt', 'Point')).not.toBeNull();
    expect(fuzzyScore('tp', 'Point')).toBeNull();
    expect(fuzzyScore('lr', 'Line reflection')!).toBeGreaterThan(fuzzyScore('lr', 'Circle')! ?? -1);
  });

  it('finds node types by label, id, category and doc', () => {
    expect(searchNodeTypes(registry.all, 'point')[0].type).toBe('point');
    expect(
      searchNodeTypes(registry.all, 'refl')
        .slice(0, 3)
        .map((d) => d.type),
    ).toContain('reflection');
    expect(searchNodeTypes(registry.all, 'line reflection')[0].type).toBe('reflection');
    expect(searchNodeTypes(registry.all, 'render')[0].type).toBe('render');
    expect(searchNodeTypes(registry.all, 'output').map((d) => d.type)).toContain('render');
    // a distinctive word of a doc line finds its node type
    const word = registry
      .get('render')!
      .doc.split(/\W+/)
      .sort((a, b) => b.length - a.length)[0];
    expect(searchNodeTypes(registry.all, word).map((d) => d.type)).toContain('render');
    expect(searchNodeTypes(registry.all, 'zzzz')).toEqual([]);
    expect(searchNodeTypes(registry.all, '')).toHaveLength(registry.all.length);
  });

  it('a dropped wire lists only node types that fit it', () => {
    const takesLine = searchNodeTypes(registry.all, '', { from: 'source', type: 'line' });
    expect(takesLine.map((d) => d.type)).toContain('reflection');
    for (const def of takesLine) expect(compatiblePort(def, { from: 'source', type: 'line' })).not.toBeNull();
    const givesPoint = searchNodeTypes(registry.all, '', { from: 'target', type: 'point' });
    expect(givesPoint[0].type).toBe('point');
    for (const def of givesPoint)
      expect(Object.values(def.outputs).some((o) => o.type === 'point')).toBe(true);
    expect(givesPoint.map((d) => d.type)).not.toContain('line');
    expect(compatiblePort(registry.get('render')!, { from: 'source', type: 'element' })).toBe('elements');
  });
});
