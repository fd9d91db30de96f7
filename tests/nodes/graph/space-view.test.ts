/**
 * Which sphairahedron a document's parameter-space view shows (nodes/graph/space-view.ts): the one
 * wired into the view node, its type and (zb, zc); none without a wire; wired zb flagged.
 */
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../../nodes/graph/document.ts';
import { spaceViewTarget } from '../../../nodes/graph/space-view.ts';

const node = (id: string, type: string, params: Record<string, unknown> = {}) => ({
  id,
  type,
  position: [0, 0] as [number, number],
  params,
});
const edge = (id: string, from: string, fromPort: string, to: string, toPort: string) => ({
  id,
  from: { node: from, port: fromPort },
  to: { node: to, port: toPort },
});
const doc = (nodes: unknown[], edges: unknown[]) =>
  ({
    format: 'kleinflow',
    version: 1,
    nodes,
    edges,
    view: { center: [0, 0], scale: 4 },
  }) as unknown as GraphDoc;

describe('spaceViewTarget', () => {
  it('is the Sphairahedron wired into the view, with its type and parameters', () => {
    const d = doc(
      [node('s', 'sphairahedron', { shape: 'prism-a', zb: 0.4, zc: 9 }), node('v', 'sphairahedron-space')],
      [edge('e', 's', 'elements', 'v', 'sphairahedron')],
    );
    const t = spaceViewTarget(d)!;
    expect(t.nodeId).toBe('s');
    expect(t.type.id).toBe('prism-a');
    expect([t.zb, t.zc, t.wired]).toEqual([0.4, 9, false]);
  });

  it('an unset type is cube A; without a wire there is no view', () => {
    const wired = doc(
      [node('s', 'sphairahedron'), node('v', 'sphairahedron-space')],
      [edge('e', 's', 'elements', 'v', 'sphairahedron')],
    );
    expect(spaceViewTarget(wired)!.type.id).toBe('cube-a');
    expect(
      spaceViewTarget(doc([node('s', 'sphairahedron'), node('v', 'sphairahedron-space')], [])),
    ).toBeNull();
  });

  it('says when zb comes from a wire (a click cannot set it)', () => {
    const d = doc(
      [node('n', 'number'), node('s', 'sphairahedron'), node('v', 'sphairahedron-space')],
      [edge('e', 's', 'elements', 'v', 'sphairahedron'), edge('f', 'n', 'value', 's', 'zb')],
    );
    expect(spaceViewTarget(d)!.wired).toBe(true);
  });
});
