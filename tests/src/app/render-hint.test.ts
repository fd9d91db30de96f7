/** The render pane's message when there is no picture: the real error, not "wire elements". */
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { renderHint } from '../../../src/app/render-hint.ts';

const doc = (renderParams: Record<string, unknown>): GraphDoc =>
  ({
    format: 'kleinflow',
    version: 1,
    meta: {},
    nodes: [
      { id: 'c', type: 'circle', position: [0, 0], params: { center: [0, 0], radius: 1 } },
      { id: 'i', type: 'inversion', position: [0, 0], params: {} },
      { id: 'out', type: 'render', position: [0, 0], params: renderParams },
    ],
    edges: [
      { id: 'e1', from: { node: 'c', port: 'circle' }, to: { node: 'i', port: 'circle' } },
      { id: 'e2', from: { node: 'i', port: 'element' }, to: { node: 'out', port: 'elements' } },
    ],
    view: { center: [0, 0], scale: 4 },
  }) as GraphDoc;

describe('renderHint', () => {
  it('names the render node’s field error when elements are wired', () => {
    const d = doc({ samples: -3 });
    const e = evaluateGraph(d, registry);
    expect(e.scene.renderNodeId).toBeNull();
    expect(renderHint(d, e)).toMatch(/^No picture: node "out" has an error \(KF\d+\): .*samples/);
  });

  it('says nothing when there is a picture', () => {
    const d = doc({});
    expect(renderHint(d, evaluateGraph(d, registry))).toBeNull();
  });
});
