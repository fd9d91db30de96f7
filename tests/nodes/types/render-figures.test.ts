import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { loadExample } from '../../support/examples.ts';

/** The example with its render node's params changed. */
function withRender(name: string, params: Record<string, unknown>): GraphDoc {
  const { doc } = loadExample(name);
  return {
    ...doc,
    nodes: doc.nodes.map((n) => (n.type === 'render' ? { ...n, params: { ...n.params, ...params } } : n)),
  };
}

describe('render node figures', () => {
  it('carries the figure options into the scene (off by default)', () => {
    expect(loadExample('fig05-limit-set').scene.figures).toEqual({
      cayleyDepth: 0,
      cayleyBase: null,
      limitSetDfs: false,
    });
    expect(loadExample('fig05-limit-set-depth-first').scene.figures?.limitSetDfs).toBe(true);
    expect(loadExample('fig01-cayley-graph').scene.figures?.cayleyDepth).toBe(4);
  });

  it('warns on the render node when the depth-first search cannot draw the group, naming why', () => {
    const ev = evaluateGraph(withRender('fig08-hyperbolic-tessellation', { limitSetDfs: true }), registry);
    const d = ev.diagnostics.find(
      (x) => x.nodeId === 'out' && /limit set \(depth-first\) not drawn/.test(x.message),
    );
    expect(d?.code).toBe('KF402');
    expect(d?.severity).toBe('warning');
    expect(d?.message).toMatch(/acts outside a bounded disk/);
  });

  it('warns when the Cayley graph meets a node it does not take, and stays quiet for one it does', () => {
    const bad = evaluateGraph(withRender('fig41-maskit-limit-set', { cayleyDepth: 3 }), registry);
    expect(bad.diagnostics.some((x) => /^Cayley graph not drawn: .*Maskit group/.test(x.message))).toBe(true);
    const good = evaluateGraph(withRender('fig08-hyperbolic-tessellation', { cayleyDepth: 3 }), registry);
    expect(good.diagnostics.some((x) => /not drawn/.test(x.message))).toBe(false);
  });
});
