import { describe, expect, it } from 'vitest';
import { LIMITS, type SeedSpec, type TileSpec } from '../../../nodes/core/scene.ts';
import { BUILTIN_PICTURE } from '../../../nodes/core/values.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { registry } from '../../../nodes/types/index.ts';
import { doc, edge, node } from '../support/doc.ts';

const evaluate = (nodes: Parameters<typeof doc>[0], edges: Parameters<typeof doc>[1] = []) =>
  evaluateGraph(doc(nodes, edges), registry);
const tileOf = (ev: ReturnType<typeof evaluate>, id = 't') => ev.nodes.get(id)!.outputs!.tile as TileSpec;

describe('seed-disk and seed-image → the tile’s seeds', () => {
  it('seeds wired into the tile arrive in graph order with their data', () => {
    const ev = evaluate(
      [
        node('c', 'circle', { center: [0.2, 0.1], radius: 0.3 }),
        node('sd', 'seed-disk', { color: '#ff0000' }),
        node('si', 'seed-image', { center: [1, 2], width: 0.5, height: 0.25, rotation: 90 }),
        node('t', 'tile', { seedsOnly: true }),
      ],
      [
        edge('e1', 'c.circle', 'sd.circle'),
        edge('e2', 'sd.seed', 't.seeds'),
        edge('e3', 'si.seed', 't.seeds'),
      ],
    );
    const tile = tileOf(ev);
    expect(tile.seeds).toHaveLength(2);
    expect(tile.seeds![0]).toEqual({ kind: 'disk', nodeId: 'sd', c: [0.2, 0.1], r: 0.3, color: [1, 0, 0] });
    const img = tile.seeds![1] as Extract<SeedSpec, { kind: 'image' }>;
    expect(img).toMatchObject({
      kind: 'image',
      center: [1, 2],
      width: 0.5,
      height: 0.25,
      image: BUILTIN_PICTURE,
    });
    expect(img.rotation).toBeCloseTo(Math.PI / 2, 12);
    expect(tile.seedsOnly).toBe(true);
  });

  it('seeds only without seeds would blank the picture: it is off until a seed is wired', () => {
    expect(tileOf(evaluate([node('t', 'tile', { seedsOnly: true })])).seedsOnly).toBe(false);
  });

  it(`more than ${LIMITS.maxSeeds} seeds: a warning, the first ${LIMITS.maxSeeds} are kept`, () => {
    const n = LIMITS.maxSeeds + 2;
    const seeds = Array.from({ length: n }, (_, i) => node(`s${i}`, 'seed-disk'));
    const ev = evaluate(
      [...seeds, node('t', 'tile')],
      seeds.map((s, i) => edge(`e${i}`, `${s.id}.seed`, 't.seeds')),
    );
    expect(tileOf(ev).seeds).toHaveLength(LIMITS.maxSeeds);
    expect(ev.nodes.get('t')!.diagnostics).toContainEqual(expect.objectContaining({ code: 'KF312' }));
  });

  it('a seed disk’s handles drag its centre and rim', () => {
    const def = registry.get('seed-disk')!;
    const ev = evaluate([node('sd', 'seed-disk')]);
    const ctx = ev.nodes.get('sd')!.ctx!;
    expect(def.drag!('center', [1, 1], ctx)).toEqual({ circle: { c: [1, 1], r: 0.1 } });
    expect(def.drag!('rim', [0.5, 0], ctx)).toEqual({ circle: { c: [0, 0], r: 0.5 } });
  });

  it('a picture seed’s corner handle scales it about its centre and turns it', () => {
    const def = registry.get('seed-image')!;
    const ev = evaluate([node('si', 'seed-image', { width: 2, height: 2 })]);
    const ctx = ev.nodes.get('si')!.ctx!;
    const change = def.drag!('corner', [-2, 2], ctx) as { width: number; height: number; rotation: number };
    expect(change.width).toBeCloseTo(4, 12);
    expect(change.height).toBeCloseTo(4, 12);
    expect(change.rotation).toBeCloseTo(90, 12);
  });
});

describe('the picture node', () => {
  const picture = (params: Record<string, unknown>) => {
    const ev = evaluate([node('p', 'image', params)]);
    return ev.nodes.get('p')!;
  };
  it('without a picture: the built-in checker with an arrow', () => {
    const r = picture({});
    expect(r.outputs!.image).toEqual(BUILTIN_PICTURE);
    expect(r.diagnostics).toEqual([]);
  });
  it('a data:image URL with its size is passed on', () => {
    const src = 'data:image/png;base64,iVBORw0KGgo=';
    expect(picture({ src, width: 20, height: 10 }).outputs!.image).toEqual({ src, width: 20, height: 10 });
  });
  it('too big, not a picture, or of unknown size: a clear warning and the built-in picture', () => {
    const big = picture({
      src: `data:image/png;base64,${'A'.repeat(LIMITS.maxImageDataUrlChars)}`,
      width: 2,
      height: 2,
    });
    expect(big.outputs!.image).toEqual(BUILTIN_PICTURE);
    expect(big.diagnostics[0]).toMatchObject({ code: 'KF310', severity: 'warning' });
    expect(big.diagnostics[0].message).toMatch(/too big \(4\.0 MB of data; the limit is 4\.0 MB\)/);
    const wide = picture({ src: 'data:image/png;base64,AA', width: LIMITS.maxPictureSide, height: 1 });
    expect(wide.diagnostics).toEqual([]);
    const http = picture({ src: 'https://example.com/a.png', width: 2, height: 2 });
    expect(http.diagnostics[0]).toMatchObject({ code: 'KF311' });
    const sizeless = picture({ src: 'data:image/png;base64,AA' });
    expect(sizeless.diagnostics[0].message).toMatch(/size 0 × 0 is not known/);
  });
});

describe('tile options', () => {
  it('fill only when fillTile is on; inner area from the wired circle; picture mode and limit set', () => {
    expect(tileOf(evaluate([node('t', 'tile')])).fill).toBeNull();
    const ev = evaluate(
      [
        node('c', 'circle', { radius: 0.5 }),
        node('p', 'image'),
        node('t', 'tile', {
          fillTile: true,
          fill: '#000000',
          mode: 'image',
          imageRotation: 180,
          imageSize: 2,
        }),
      ],
      [edge('e1', 'c.circle', 't.inner'), edge('e2', 'p.image', 't.image')],
    );
    const tile = tileOf(ev);
    expect(tile.fill).toEqual([0, 0, 0]);
    expect(tile.inner).toEqual({ c: [0, 0], r: 0.5 });
    expect(tile.coloring).toMatchObject({ mode: 'image', image: BUILTIN_PICTURE, size: 2, center: [0, 0] });
    expect((tile.coloring as { rotation: number }).rotation).toBeCloseTo(Math.PI, 12);
    expect(tileOf(evaluate([node('t', 'tile', { mode: 'limit-set', glow: 3 })])).coloring).toEqual({
      mode: 'limit-set',
      glow: 3,
    });
  });

  it('picture mode: handles move the picture, and scale and turn it from its top', () => {
    const def = registry.get('tile')!;
    const ev = evaluate([node('t', 'tile', { mode: 'image' })]);
    const ctx = ev.nodes.get('t')!.ctx!;
    const handles = def.handles!(ctx, ev.nodes.get('t')!.outputs!);
    expect(handles.map((x) => x.handle)).toEqual(['picture-center', 'picture-top']);
    expect(handles[1].at[0]).toBeCloseTo(0, 12);
    expect(handles[1].at[1]).toBeCloseTo(0.5, 12);
    expect(def.drag!('picture-center', [1, 2], ctx)).toEqual({ imageCenter: [1, 2] });
    const turn = def.drag!('picture-top', [-1, 0], ctx) as { imageSize: number; imageRotation: number };
    expect(turn.imageSize).toBeCloseTo(2, 12);
    expect(turn.imageRotation).toBeCloseTo(90, 12);
    expect(def.handles!(evaluate([node('t', 'tile')]).nodes.get('t')!.ctx!, {})).toEqual([]);
  });

  it('a picture of no height is refused with a reason', () => {
    const r = evaluate([node('t', 'tile', { mode: 'image', imageSize: 0 })]).nodes.get('t')!;
    expect(r.outputs).toBeUndefined();
    expect(r.diagnostics[0].message).toMatch(/picture height must be positive/);
  });
});
