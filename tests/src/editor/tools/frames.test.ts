/** Frames move the nodes inside them (one change); reroute points go on the nearest segment. */
import { describe, expect, it } from 'vitest';
import { registry } from '../../../../nodes/types/index.ts';
import { frameAround, moveFrame, nodesInFrame } from '../../../../src/editor/tools/frames.ts';
import { allMuted, muteToggle } from '../../../../src/editor/tools/mute.ts';
import { insertVia, polylinePath } from '../../../../src/editor/tools/reroute.ts';
import { applyChange } from '../../../../src/state/changes.ts';
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
