import { describe, expect, it } from 'vitest';
import type { HandleItem } from '../../../../nodes/core/scene.ts';
import { dist } from '../../../../nodes/geometry/vec.ts';
import { evaluateGraph } from '../../../../nodes/graph/evaluate.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { snapHandle } from '../../../../src/viewport/overlay/snap-rules.ts';
import { doc, edge, node } from './fixtures.ts';

const PX_PER_WORLD = 150; // 600 px pane showing 4 world units: grid step 0.2, 12 px = 0.08

const handleOf = (ev: ReturnType<typeof evaluateGraph>, nodeId: string, handle: string): HandleItem =>
  ev.scene.handles.find((h) => h.nodeId === nodeId && h.handle === handle)!;

describe('snapHandle', () => {
  it('snaps a free point and a circle centre to the grid', () => {
    const ev = evaluateGraph(doc([node('p', 'point'), node('c', 'circle')]), registry);
    expect(snapHandle(ev.scene.overlays, handleOf(ev, 'p', 'point'), [0.33, 0.51], PX_PER_WORLD)).toEqual({
      at: [0.4, 0.6000000000000001],
      guide: { kind: 'grid', step: 0.2 },
    });
    const centre = snapHandle(ev.scene.overlays, handleOf(ev, 'c', 'center'), [0.09, -0.11], PX_PER_WORLD);
    expect(centre.guide.kind).toBe('grid');
    expect(centre.at[0]).toBeCloseTo(0, 12);
    expect(centre.at[1]).toBeCloseTo(-0.2, 12);
  });

  it('turns a line end about the other end to 15° steps, its own or a wired point', () => {
    const ev = evaluateGraph(
      doc(
        [node('p', 'point', { x: 0, y: 0 }), node('l', 'line', { b: [1, 0] })],
        [edge('p', 'point', 'l', 'a')],
      ),
      registry,
    );
    const b = snapHandle(ev.scene.overlays, handleOf(ev, 'l', 'b'), [1, 0.95], PX_PER_WORLD);
    expect(b.guide).toEqual({ kind: 'angle', pivot: [0, 0], degrees: 45 });
    expect(b.at[0]).toBeCloseTo(b.at[1], 12);
    expect(dist(b.at, [0, 0])).toBeCloseTo(Math.hypot(1, 0.95), 12);
    const a = snapHandle(ev.scene.overlays, handleOf(ev, 'p', 'point'), [0.02, -0.5], PX_PER_WORLD);
    expect(a.guide).toEqual({ kind: 'angle', pivot: [1, 0], degrees: -150 });
  });

  it('turns a line end to meet another drawn line at π/n (n ≤ 12) when that is nearer than a 15° step', () => {
    // Line l1 at 10° through the origin; l2 from (3, 0) is dragged near 10° + π/7 ≈ 35.71°.
    const t = (10 * Math.PI) / 180;
    const ev = evaluateGraph(
      doc([
        node('l1', 'line', { a: [0, 0], b: [Math.cos(t), Math.sin(t)] }),
        node('l2', 'line', { a: [3, 0], b: [4, 0] }),
      ]),
      registry,
    );
    const want = [3 + Math.cos(t + Math.PI / 7 + 0.01), Math.sin(t + Math.PI / 7 + 0.01)] as [number, number];
    const s = snapHandle(ev.scene.overlays, handleOf(ev, 'l2', 'b'), want, PX_PER_WORLD);
    expect(s.guide.kind === 'angle' && s.guide.piOver?.n).toBe(7);
    const dir = Math.atan2(s.at[1], s.at[0] - 3);
    expect(dir - t).toBeCloseTo(Math.PI / 7, 12);
    expect(dist(s.at, [3, 0])).toBeCloseTo(1, 12);
  });

  it('makes a dragged rim tangent to a nearby circle, else rounds the radius to the grid', () => {
    const ev = evaluateGraph(
      doc([
        node('c', 'circle', { center: [0, 0], radius: 1 }),
        node('o', 'circle', { center: [3, 0], radius: 1 }),
      ]),
      registry,
    );
    const rim = handleOf(ev, 'c', 'rim');
    const near = snapHandle(ev.scene.overlays, rim, [2.05, 0], PX_PER_WORLD);
    expect(near.guide).toEqual({ kind: 'tangent', center: [0, 0], touching: { c: [3, 0], r: 1 } });
    expect(near.at).toEqual([2, 0]);
    const far = snapHandle(ev.scene.overlays, rim, [0, 1.23], PX_PER_WORLD);
    expect(far.guide.kind).toBe('radius');
    expect(far.at[1]).toBeCloseTo(1.2, 12);
    // Beyond 12 px (0.08) from tangency: no pull.
    expect(snapHandle(ev.scene.overlays, rim, [1.9, 0], PX_PER_WORLD).guide.kind).toBe('radius');
  });
});
