/**
 * The tile options and the program's identity (its source text, which the runtime caches programs
 * by): what changes the code changes the source, values never do.
 */
import { describe, expect, it } from 'vitest';
import type { Scene, SeedSpec, TileSpec } from '../../nodes/core/scene.ts';
import { BUILTIN_PICTURE } from '../../nodes/core/values.ts';
import { compile } from '../../shader-gen/compile.ts';
import { makeScene, SCHOTTKY, SEED_DISK, SEED_PICTURE } from './support/scenes.ts';

const base = makeScene(SCHOTTKY, { scale: 5 });
const withTile = (tile: Partial<TileSpec>, scene: Scene = base): Scene => ({
  ...scene,
  tile: { ...scene.tile, ...tile },
});
const source = (s: Scene) => compile(s).source;
const other = (seed: SeedSpec, src: string): SeedSpec =>
  seed.kind === 'image' ? { ...seed, image: { ...seed.image, src } } : seed;

describe('program identity: tile options', () => {
  it('changes with fill, seed kinds/count, seeds only, inner area, limit glow, picture sharing', () => {
    const variants: Scene[] = [
      base,
      withTile({ fill: [0, 0, 0] }),
      withTile({ seeds: [SEED_DISK] }),
      withTile({ seeds: [SEED_DISK, SEED_DISK] }),
      withTile({ seeds: [SEED_PICTURE] }),
      withTile({ seeds: [SEED_DISK], seedsOnly: true }),
      withTile({ seeds: [SEED_DISK], seedFade: 0.1 }),
      withTile({ inner: { c: [0, 0], r: 1 } }),
      withTile({ coloring: { mode: 'limit-set', glow: 0 } }),
      withTile({ coloring: { mode: 'limit-set', glow: 2 } }),
      withTile({ seeds: [SEED_PICTURE, SEED_PICTURE] }),
      withTile({ seeds: [SEED_PICTURE, other(SEED_PICTURE, 'data:image/png;base64,AA')] }),
    ];
    const sources = variants.map(source);
    expect(new Set(sources).size).toBe(sources.length);
  });

  it('stays when only values move: seed place and colour, fill colour, inner circle, glow width, the picture itself', () => {
    const a = withTile({ fill: [0, 0, 0], seeds: [SEED_DISK, SEED_PICTURE], inner: { c: [0, 0], r: 1 } });
    const b = withTile({
      fill: [1, 0.5, 0],
      seeds: [
        { ...SEED_DISK, c: [0.3, 0.2], r: 0.2, color: [0, 1, 0] } as SeedSpec,
        { ...other(SEED_PICTURE, 'data:image/png;base64,BB'), rotation: 2 } as SeedSpec,
      ],
      inner: { c: [1, 0], r: 0.4 },
    });
    expect(source(b)).toBe(source(a));
    expect(compile(b).pictures).toEqual(['data:image/png;base64,BB']);
    const glow = (g: number) => withTile({ coloring: { mode: 'limit-set', glow: g } });
    expect(source(glow(1))).toBe(source(glow(7)));
  });

  it('a baked program holds a picture by its sampler, not its (long) data', () => {
    const pic = (src: string) =>
      withTile({
        coloring: { mode: 'image', image: { ...BUILTIN_PICTURE, src }, center: [0, 0], size: 1, rotation: 0 },
      });
    const baked = (s: Scene) => compile(s, { baked: true });
    const [a, b] = [baked(pic('data:image/png;base64,AA')), baked(pic('data:image/png;base64,BB'))];
    expect(b.source).toBe(a.source);
    expect(b.source).not.toContain('base64');
    expect([a.pictures, b.pictures]).toEqual([['data:image/png;base64,AA'], ['data:image/png;base64,BB']]);
  });
});
