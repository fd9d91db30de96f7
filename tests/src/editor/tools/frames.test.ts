/** Frames move the nodes inside them (one change); reroute points go on the nearest segment. */
import { describe, expect, it } from 'vitest';
import { groupNodes, ungroupNode } from '../../../../nodes/graph/grouping.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { frameAround, moveFrame, nodesInFrame } from '../../../../src/editor/tools/frames.ts';
import { allMuted, muteToggle } from '../../../../src/editor/tools/mute.ts';
import { insertVia, polylinePath } from '../../../../src/editor/tools/reroute.ts';
import { applyChange, type Change } from '../../../../src/state/changes.ts';
import { scopeDocument } from '../../../../src/state/group-changes.ts';
import { idAllocator } from '../../../../src/state/ids.ts';
import { doc, node } from '../../../nodes/support/doc.ts';

const at = (id: string, x: number, y: number) => ({
  ...node(id, 'point'),
  position: [x, y] as [number, number],
});
const d = () => doc([at('a', 0, 0), at('b', 300, 100), at('far', 2000, 0)]);

describe('frames', () => {
  it('a frame around the selection encloses it; moving it moves exactly those nodes', () => {
    const change = frameAround(d(), new Set(['a', 'b']));
    expect(change?.type).toBe('put-frame');
    const framed = applyChange(d(), change!, registry);
    const frame = framed.frames![0];
    expect(frame).toMatchObject({ id: 'frame1', title: 'Frame 1' });
    expect(nodesInFrame(framed, frame)).toEqual(['a', 'b']);
    const moved = applyChange(framed, moveFrame(framed, frame.id, 40, -10)!, registry);
    expect(moved.nodes.map((n) => n.position)).toEqual([
      [40, -10],
      [340, 90],
      [2000, 0],
    ]);
    expect(moved.frames![0].position).toEqual([frame.position[0] + 40, frame.position[1] - 10]);
    expect(moveFrame(framed, frame.id, 0, 0)).toBeNull();
    expect(frameAround(d(), new Set())).toBeNull();
  });

  it('inside an open group: made, retitled and moved in the group’s body; ungrouping brings it out', () => {
    const top = groupNodes(d(), ['a', 'b'], 'g');
    const inGroup = (change: Change): Change => ({ type: 'in-group', path: ['g'], change });
    const made = applyChange(
      top,
      inGroup(frameAround(scopeDocument(top, ['g'])!, new Set(['a']))!),
      registry,
    );
    expect(made.frames).toBeUndefined(); // not at the top level
    const inside = scopeDocument(made, ['g'])!;
    const frame = inside.frames![0];
    expect(made.nodes[0].group?.frames).toEqual([frame]);
    expect(nodesInFrame(inside, frame)).toEqual(['a']);
    const titled = applyChange(
      made,
      inGroup({ type: 'put-frame', frame: { ...frame, title: 'Mirrors' } }),
      registry,
    );
    const moved = applyChange(
      titled,
      inGroup(moveFrame(scopeDocument(titled, ['g'])!, frame.id, 20, 0)!),
      registry,
    );
    const body = moved.nodes[0].group!;
    expect(body.frames).toEqual([
      { ...frame, title: 'Mirrors', position: [frame.position[0] + 20, frame.position[1]] },
    ]);
    expect(body.nodes.map((n) => n.position)).toEqual([
      [20, 0],
      [300, 100],
    ]);
    // The document round trip keeps it, and ungrouping puts it at the top level with its node.
    const back = ungroupNode(moved, 'g', idAllocator(moved));
    // Ungrouped nodes land at the group node (here 20 left of where they were inside): so does it.
    const a = (g: typeof moved) => (g.nodes.find((n) => n.id === 'a') ?? body.nodes[0]).position;
    const dx = a(back)[0] - body.nodes[0].position[0];
    expect(back.frames).toEqual(
      body.frames!.map((f) => ({ ...f, position: [f.position[0] + dx, f.position[1]] })),
    );
    expect(nodesInFrame(back, back.frames![0])).toEqual(['a']);
  });
});

describe('mute toggle', () => {
  it('mutes the selection unless all of it is muted', () => {
    const m = applyChange(d(), muteToggle(d(), new Set(['a']))!, registry);
    expect(allMuted(m, new Set(['a']))).toBe(true);
    expect(muteToggle(m, new Set(['a', 'b']))).toMatchObject({ muted: true });
    expect(muteToggle(m, new Set(['a']))).toMatchObject({ muted: false });
    expect(muteToggle(m, new Set())).toBeNull();
  });
});

describe('reroute points', () => {
  it('a new point goes between the two points the wire passes nearest', () => {
    expect(insertVia([0, 0], [], [100, 0], [50, 5])).toEqual([[50, 5]]);
    expect(insertVia([0, 0], [[50, 50]], [100, 0], [90, 20])).toEqual([
      [50, 50],
      [90, 20],
    ]);
    expect(insertVia([0, 0], [[50, 50]], [100, 0], [10, 20])).toEqual([
      [10, 20],
      [50, 50],
    ]);
    expect(
      polylinePath([
        [0, 0],
        [1, 2],
      ]),
    ).toBe('M 0 0 L 1 2');
  });
});
