import { describe, expect, it } from 'vitest';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { fixPatches } from '../../../src/editor/diagnostic-fix.ts';
import { doc, edge, node } from '../viewport/overlay/fixtures.ts';

describe('fixPatches', () => {
  const d = doc(
    [node('p', 'point', { x: 0, y: 0 }), node('l', 'line', { b: [1, 0] }), node('m', 'reflection')],
    [edge('p', 'point', 'l', 'a'), edge('l', 'line', 'm', 'line')],
  );
  const ev = evaluateGraph(d, registry);

  it('applies params as given and merges several for one node', () => {
    expect(
      fixPatches(ev, {
        label: 'x',
        params: [
          { nodeId: 'm', params: { flip: true } },
          { nodeId: 'm', params: { visible: false } },
        ],
      }),
    ).toEqual([{ nodeId: 'm', params: { flip: true, visible: false } }]);
  });

  it('moves a handle like a drag: a wired end moves the upstream point, a free end the line itself', () => {
    expect(fixPatches(ev, { label: 'x', moves: [{ nodeId: 'l', handle: 'a', to: [0.5, 2] }] })).toEqual([
      { nodeId: 'p', params: { x: 0.5, y: 2 } },
    ]);
    expect(fixPatches(ev, { label: 'x', moves: [{ nodeId: 'l', handle: 'b', to: [3, 4] }] })).toEqual([
      { nodeId: 'l', params: { b: [3, 4] } },
    ]);
  });
});
