import { describe, expect, it } from 'vitest';
import { elementNames } from '../../../nodes/graph/element-names.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { loadExample } from '../../support/examples.ts';

describe('elementNames', () => {
  it('numbers the mirrors of one node and falls back to the type label', () => {
    const { doc } = loadExample('hyperbolic-237');
    const ev = evaluateGraph(doc, registry);
    expect(elementNames(ev.scene.elements, ev.analysis)).toEqual([
      'Triangle kaleidoscope 1',
      'Triangle kaleidoscope 2',
      'Triangle kaleidoscope 3',
    ]);
  });

  it('uses the node labels, unnumbered for a node with one element', () => {
    const { doc } = loadExample('apollonian-gasket');
    const ev = evaluateGraph(doc, registry);
    const names = elementNames(ev.scene.elements, ev.analysis);
    const labelled = ev.scene.elements.map((e) => doc.nodes.find((n) => n.id === e.nodeId)?.label);
    expect(names).toHaveLength(ev.scene.elements.length);
    names.forEach((name, i) => {
      if (labelled[i]) expect(name).toBe(labelled[i]);
    });
    expect(new Set(names).size).toBe(names.length);
    expect(names).toContain('Circle inversion “iABC”');
  });
});
