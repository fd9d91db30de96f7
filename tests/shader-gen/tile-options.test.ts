/**
 * The tile options on the CPU (colour.ts shade, raster.ts sampleColour): tile fill, orbit seeds,
 * seeds only, the picture kaleidoscope, the limit-set colouring, the inner area, tile edges near
 * inversion centres, and the inversion-centre guard. The GPU twins are checked by tests/parity.
 */
import { describe, expect, it } from 'vitest';
import type { Coloring, Scene, SceneElement, SeedSpec, TileSpec } from '../../nodes/core/scene.ts';
import { BUILTIN_PICTURE, type Color } from '../../nodes/core/values.ts';
import { CENTRE_GUARD } from '../../shader-gen/elements/inversion.ts';
import { farDisk, farDistance, limitReach } from '../../shader-gen/far-disk.ts';
import { interpret } from '../../shader-gen/interpret.ts';
import { builtinPicture, samplePicture } from '../../shader-gen/picture.ts';
import { placeUv } from '../../shader-gen/placement.ts';
import { rasterize, sampleColour, sampleContext } from '../../shader-gen/raster.ts';
import { seedAt } from '../../shader-gen/seeds.ts';
import { toLinear } from '../../shader-gen/srgb.ts';
import { COLORINGS, inversion, makeScene, reflection, SCHOTTKY } from './support/scenes.ts';

const RED: Color = [1, 0, 0];
const BLUE: Color = [0, 0, 1];
const GOLD: Color = [1, 0.8, 0.2];
const BG: Color = [0.06, 0.06, 0.08];
/** The mirror y = 0 keeping y > 0: depth 0 above, depth 1 below. */
const MIRROR: SceneElement[] = [reflection('m', [0, 0], [0, 1])];
const two = { mode: 'parity', even: RED, odd: BLUE } as const;
const PICTURE = COLORINGS.image as Extract<Coloring, { mode: 'image' }>;

function colourAt(scene: Scene, x: number, y: number, pixelWorld = 0.01) {
  return sampleColour(scene, sampleContext(scene), x, y, pixelWorld, { x: 0, y: 0, s: 1, depth: 0 });
}
const withTile = (elements: SceneElement[], tile: Partial<TileSpec>) =>
  makeScene(elements, { coloring: two, tile });
const disk = (c: [number, number], r: number, color = GOLD): SeedSpec => ({
  kind: 'disk',
  nodeId: 's',
  c,
  r,
  color,
});

describe('tile fill: depth 0 in its own colour', () => {
  it('the tile takes the fill, its images keep their depth colour', () => {
    const s = withTile(MIRROR, { fill: GOLD });
    expect(colourAt(s, 0.2, 0.5)).toEqual(toLinear(GOLD));
    expect(colourAt(s, 0.2, -0.5)).toEqual(toLinear(BLUE));
    expect(colourAt(withTile(MIRROR, {}), 0.2, 0.5)).toEqual(toLinear(RED));
  });
});

describe('orbit seeds (tested at the start of every step)', () => {
  it('a seed disk in the tile paints itself and its mirror image', () => {
    const s = withTile(MIRROR, { seeds: [disk([0, 0.5], 0.2)] });
    expect(colourAt(s, 0.1, 0.5)).toEqual(toLinear(GOLD)); // the seed itself
    expect(colourAt(s, 0.1, -0.5)).toEqual(toLinear(GOLD)); // its image below the mirror
    expect(colourAt(s, 0.5, -0.5)).toEqual(toLinear(BLUE)); // beside the image: depth 1
  });

  it('a seed across the mirror is found at depth 0, before the element moves the point', () => {
    const s = withTile(MIRROR, { seeds: [disk([0, -0.5], 0.2)] });
    expect(colourAt(s, 0, -0.5)).toEqual(toLinear(GOLD));
    expect(colourAt(s, 0, 0.5)).toEqual(toLinear(RED)); // never reached from above
  });

  it('the first seed in order wins; seedAt is strict at the rim', () => {
    const seeds = [disk([0, 0.5], 0.2, GOLD), disk([0, 0.5], 0.4, BLUE)];
    expect(seedAt(seeds, 0, 0.5)).toBe(0);
    expect(seedAt(seeds, 0, 0.8)).toBe(1);
    expect(seedAt(seeds, 0, 0.9)).toBe(-1);
    expect(seedAt(seeds, 0.4, 0.5)).toBe(-1);
  });

  it('seed fade: an image met after n steps is darkened by max(0, 1 − fade·n)', () => {
    const s = withTile(MIRROR, { seeds: [disk([0, 0.5], 0.2)], seedFade: 0.25 });
    expect(colourAt(s, 0.1, 0.5)).toEqual(toLinear(GOLD));
    expect(colourAt(s, 0.1, -0.5)).toEqual(toLinear(GOLD).map((c) => c * 0.75));
  });

  it('seeds only: everything but the orbit is background (the paper’s Fig. 2)', () => {
    const s = withTile(MIRROR, { seeds: [disk([0, 0.5], 0.2)], seedsOnly: true });
    expect(colourAt(s, 0.1, -0.5)).toEqual(toLinear(GOLD));
    expect(colourAt(s, 0.5, -0.5)).toEqual(toLinear(BG));
    expect(colourAt(s, 0.5, 0.5)).toEqual(toLinear(BG));
  });

  it('a picture seed paints its picture’s texel at the point, and at every image of it', () => {
    const seed: SeedSpec = {
      kind: 'image',
      nodeId: 'p',
      center: [0, 0.5],
      width: 0.4,
      height: 0.3,
      rotation: 0.3,
      image: BUILTIN_PICTURE,
    };
    const s = withTile(MIRROR, { seeds: [seed] });
    const [u, v] = placeUv(0, 0.5, 0.4, 0.3, Math.cos(0.3), Math.sin(0.3), 0.05, 0.55);
    const texel = samplePicture(builtinPicture(), u, v);
    expect(colourAt(s, 0.05, 0.55)).toEqual(texel);
    expect(colourAt(s, 0.05, -0.55)).toEqual(texel);
    expect(colourAt(s, 0.3, 0.5)).toEqual(toLinear(RED)); // outside the turned rectangle
  });
});

describe('the picture kaleidoscope: the picture at the final point', () => {
  it('every image of a point shows the texel of its final point in the tile', () => {
    const s = makeScene(MIRROR, { coloring: { ...PICTURE, center: [0, 0], size: 2, rotation: 0 } });
    const [u, v] = placeUv(0, 0, 2, 2, 1, 0, 0.3, 0.4);
    expect(colourAt(s, 0.3, 0.4)).toEqual(samplePicture(builtinPicture(), u, v));
    expect(colourAt(s, 0.3, -0.4)).toEqual(colourAt(s, 0.3, 0.4)); // mirrored copy
  });

  it('a picture the raster was not given is an error that names it', () => {
    const s = makeScene(MIRROR, {
      coloring: { ...PICTURE, image: { src: 'data:image/png;base64,xyz', width: 4, height: 4 } },
    });
    expect(() => rasterize(s, { width: 2, height: 2 })).toThrow(/data:image\/png;base64,xyz.*not decoded/);
  });
});

describe('limit set only', () => {
  const schottky = (glow: number) =>
    makeScene(SCHOTTKY, {
      coloring: { mode: 'limit-set', glow },
      maxIterations: 40,
      scale: 5,
      tile: { limitColor: [1, 1, 1] },
    });
  it('not escaped → limit colour; far from the limit set → background; with glow, brighter near it', () => {
    const s = schottky(0);
    const limit = toLinear(s.tile.limitColor);
    const bg = toLinear(s.tile.background);
    expect(colourAt({ ...s, maxIterations: 0 }, -1, 0)).toEqual(limit); // inside an element at maxIter 0
    expect(colourAt(s, 2.4, 2.4)).toEqual(bg);
    const near = colourAt(schottky(4), 2.4, 2.4, 0.5); // coarse pixels: the set is a few pixels away
    expect(near[0]).toBeGreaterThan(bg[0]);
  });
  it('the reach is the smallest inside radius; none for mirrors only', () => {
    expect(limitReach(SCHOTTKY)).toBeCloseTo(0.5, 12);
    expect(limitReach(MIRROR)).toBeNull();
  });
});

describe('internal area (Fig. 22)', () => {
  it('keeps the colour only where the final point lies inside the inner circle', () => {
    const s = withTile(MIRROR, { inner: { c: [0, 0.5], r: 0.2 } });
    expect(colourAt(s, 0.1, 0.5)).toEqual(toLinear(RED));
    expect(colourAt(s, 0.1, -0.5)).toEqual(toLinear(BLUE)); // its image ends inside too
    expect(colourAt(s, 0.5, -0.5)).toEqual(toLinear(BG));
  });
});

describe('inversion centres', () => {
  it('the centre itself goes to a far point on +x, deterministically and finitely', () => {
    const r = interpret({ elements: [inversion('i', [0.5, -0.25], 0.4)], maxIterations: 10 }, [0.5, -0.25]);
    expect(r).toMatchObject({ depth: 1, escaped: true });
    // c + (r/G)·G² = c + (r·G, 0), up to the rounding of r/G
    expect(r.final[0] / (0.4 * CENTRE_GUARD)).toBeCloseTo(1, 14);
    expect(r.final[1]).toBe(-0.25);
    expect(r.scale).toBe(CENTRE_GUARD * CENTRE_GUARD);
  });

  it('no dot of edge colour at an inversion centre (the far chart measures the distance)', () => {
    const c: [number, number] = [0.3, 0.1];
    const elements = [inversion('a', c, 0.5), inversion('b', [-1, 0], 0.3)];
    const s = makeScene(elements, { coloring: two, edgeWidth: 3 });
    const pixel = 0.002;
    const edge = toLinear(s.tile.edgeColor);
    for (const off of [0, 0.3, 1, 2]) {
      expect(colourAt(s, c[0] + off * pixel, c[1], pixel), `${off} px from the centre`).toEqual(
        toLinear(BLUE),
      );
    }
    // …while the rim itself still has its edge.
    expect(colourAt(s, c[0] + 0.5, c[1] + 1e-9, pixel)).toEqual(edge);
  });

  it('far chart: (R − ρ)·R/ρ beyond the bounding circle, 0 inside; null with an unbounded inside', () => {
    const far = farDisk([inversion('a', [1, 0], 1), inversion('b', [-1, 0], 1)])!;
    expect(far).toEqual({ c: [0, 0], r: 2 });
    expect(farDistance(far, 1, 0)).toBe(0);
    expect(farDistance(far, 4, 0)).toBe(4);
    expect(farDisk([...MIRROR, inversion('a', [1, 0], 1)])).toBeNull();
  });
});
