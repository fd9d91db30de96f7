import { describe, expect, it } from 'vitest';
import { createRegistry } from '../../../../nodes/core/registry.ts';
import type { SeedSpec } from '../../../../nodes/core/scene.ts';
import { BUILTIN_PICTURE } from '../../../../nodes/core/values.ts';
import { worldToPixel } from '../../../../nodes/core/view.ts';
import { NODE_TYPES } from '../../../../nodes/types/index.ts';
import { rasterize, sampleColour, sampleContext } from '../../../../shader-gen/raster.ts';
import { seedColour } from '../../../../shader-gen/seeds.ts';
import { importFlower } from '../../../../src/io/flower/import.ts';
import { FLOWER_SEED_SIZE } from '../../../../src/io/flower/orbit-seed.ts';
import { fedge, fnode, fpoint, graph, lineMirror } from './support/flower-fixture.ts';
import { imported, messages } from './support/imported.ts';

type ImageSeed = Extract<SeedSpec, { kind: 'image' }>;
/** A mirror along the x-axis keeping y > 0 (the left of (0,0) → (1,0)), and one OrbitSeed. */
const withMirror = (seed: Record<string, unknown>) =>
  graph(lineMirror('m', [0, 0], [1, 0], false), { nodes: [fnode('OrbitSeed', 'os', seed)], edges: [] });

describe('Flower import: OrbitSeed', () => {
  it('becomes a seed picture placed by its lower-left corner, wired into the tile, with notes', () => {
    const { doc, scene, errors, notes } = imported(
      withMirror({ cornerX: 5, cornerY: 10, width: 30, height: 20 }),
    );
    expect(errors).toEqual([]);
    const seed = doc.nodes.find((n) => n.type === 'seed-image')!;
    expect(seed.params).toEqual({ center: [20, 20], width: 30, height: 20, rotation: 0 });
    const tile = doc.nodes.find((n) => n.type === 'tile')!;
    expect(doc.edges).toContainEqual(
      expect.objectContaining({
        from: { node: seed.id, port: 'seed' },
        to: { node: tile.id, port: 'seeds' },
      }),
    );
    expect(scene.tile.seeds).toEqual([
      {
        kind: 'image',
        nodeId: seed.id,
        center: [20, 20],
        width: 30,
        height: 20,
        rotation: 0,
        image: BUILTIN_PICTURE,
      },
    ]);
    expect(messages(notes)).toEqual([
      expect.stringMatching(/OrbitSeed "os": Flower's seed picture is not carried over; .*built-in picture/),
      expect.stringMatching(
        /fields are guessed: the seed rectangle was read from cornerX\/cornerY as its lower-left corner, width, height$/,
      ),
    ]);
    for (const n of notes) expect(n.code).toBe('KF502');
  });

  it('the picture is painted where the seed is and at its mirror image; the rest of the tile stays black', () => {
    const { scene } = imported(withMirror({ cornerX: 5, cornerY: 10, width: 30, height: 20 }));
    const seed = scene.tile.seeds![0] as ImageSeed;
    const ctx = sampleContext(scene);
    const st = { x: 0, y: 0, s: 1, depth: 0 };
    const at = (x: number, y: number) => sampleColour(scene, ctx, x, y, 0.1, st);
    for (const [x, y] of [
      [20, 20],
      [8, 12],
      [33, 28],
    ]) {
      const picture = seedColour(seed, x, y, undefined);
      expect(at(x, y)).toEqual(picture);
      // Its image under the mirror (y → −y) shows the same texel.
      expect(at(x, -y)).toEqual(picture);
    }
    expect(at(-20, 20)).toEqual([0, 0, 0]); // the tile, outside the seed: Flower's black
    expect(at(-20, -20)).not.toEqual([0, 0, 0]); // the tile's image: Flower's first hue

    // The whole CPU picture: inside the seed's rectangle (and its mirror image) every pixel is lit.
    const size = 64;
    const raster = rasterize(scene, { width: size, height: size, samples: 1 });
    const lit = (x: number, y: number) => {
      const [px, py] = worldToPixel(scene.view, size, size, [x, y]).map(Math.floor);
      const k = ((size - 1 - py) * size + px) * 4; // pixel rows count up, raster rows down
      return raster.data[k] + raster.data[k + 1] + raster.data[k + 2] > 30;
    };
    let inside = 0;
    for (let x = 7; x <= 33; x += 2)
      for (let y = 12; y <= 28; y += 2) {
        inside++;
        expect([x, y, lit(x, y), lit(x, -y)]).toEqual([x, y, true, true]);
      }
    expect(inside).toBeGreaterThan(100);
    expect(lit(-20, 20)).toBe(false);
    expect(lit(-20, -20)).toBe(true);
  });

  it('reads other likely field names: a centre, posX/posY with a size, a corner array with rotation', () => {
    const centred = imported(withMirror({ centerX: 1, centerY: 2, width: 4, height: 6 })).doc;
    expect(centred.nodes.find((n) => n.type === 'seed-image')!.params).toEqual({
      center: [1, 2],
      width: 4,
      height: 6,
      rotation: 0,
    });
    const pos = imported(withMirror({ posX: -3, posY: 4, size: 2 }));
    expect(pos.doc.nodes.find((n) => n.type === 'seed-image')!.params).toEqual({
      center: [-2, 5],
      width: 2,
      height: 2,
      rotation: 0,
    });
    expect(messages(pos.notes)[1]).toMatch(/read from posX\/posY as its lower-left corner, size$/);
    // Turned a quarter about its corner (0, 0): the rectangle [0,4]×[0,2] goes to [−2,0]×[0,4].
    const turned = imported(
      withMirror({ corner: [0, 0], width: 4, height: 2, rotationRadians: Math.PI / 2 }),
    );
    const p = turned.doc.nodes.find((n) => n.type === 'seed-image')!.params as Record<
      string,
      number[] & number
    >;
    expect(p.center[0]).toBeCloseTo(-1, 12);
    expect(p.center[1]).toBeCloseTo(2, 12);
    expect(p.rotation).toBeCloseTo(90, 12);
    expect(messages(turned.notes)[1]).toMatch(
      /read from corner as its lower-left corner, width, height, rotationRadians \(radians\)$/,
    );
    expect(turned.errors).toEqual([]);
  });

  it('says what was missing: no position → the origin, no size → a square a tenth of the view', () => {
    const { doc, notes, errors } = imported(withMirror({}));
    expect(errors).toEqual([]);
    expect(doc.nodes.find((n) => n.type === 'seed-image')!.params).toEqual({
      center: [0, 0],
      width: FLOWER_SEED_SIZE,
      height: FLOWER_SEED_SIZE,
      rotation: 0,
    });
    expect(messages(notes)).toEqual([
      expect.stringMatching(/picture is not carried over/),
      expect.stringMatching(/no saved position found; the seed is placed at the origin/),
      expect.stringMatching(/no saved width or height found; a 10 × 10 square/),
    ]);
    const tall = imported(withMirror({ cornerX: 0, cornerY: 0, height: 8, width: 0 }));
    expect(tall.doc.nodes.find((n) => n.type === 'seed-image')!.params).toMatchObject({
      width: 8,
      height: 8,
    });
    expect(messages(tall.notes)).toContainEqual(
      expect.stringMatching(/no saved width found; the seed is made square/),
    );
  });

  it("wires Flower's inputs: a point sets the centre, Floats the width and height", () => {
    const json = graph(lineMirror('m', [0, 0], [1, 0], false), {
      nodes: [
        fpoint('q', 3, 7),
        fnode('Constant', 'k', { value: 5 }),
        fnode('OrbitSeed', 'os', { cornerX: 100, cornerY: 100, height: 2 }, [['Point', 'Float'], []]),
      ],
      edges: [fedge('Point', 'q', 'os', 0), fedge('Float', 'k', 'os', 1, true)],
    });
    const { doc, scene, errors, notes } = imported(json);
    expect(errors).toEqual([]);
    const seedId = doc.nodes.find((n) => n.type === 'seed-image')!.id;
    const into = doc.edges.filter((e) => e.to.node === seedId).map((e) => e.to.port);
    expect(into).toEqual(['center', 'width']);
    expect(scene.tile.seeds).toEqual([expect.objectContaining({ center: [3, 7], width: 5, height: 2 })]);
    const text = messages(notes);
    expect(text).toContainEqual(expect.stringMatching(/the point wired into it sets the seed's centre/));
    expect(text).not.toContainEqual(expect.stringMatching(/no saved (position|width)/));
  });

  it('several seeds reach the tile in file order', () => {
    const json = graph(lineMirror('m', [0, 0], [1, 0], false), {
      nodes: [
        fnode('OrbitSeed', 'a', { centerX: 1, centerY: 1, width: 1, height: 1 }),
        fnode('OrbitSeed', 'b', { centerX: 5, centerY: 5, width: 2, height: 2 }),
      ],
      edges: [],
    });
    const { scene } = imported(json);
    expect(scene.tile.seeds?.map((s) => (s as ImageSeed).center)).toEqual([
      [1, 1],
      [5, 5],
    ]);
  });

  it('without a seed-image node type the seed is reported and skipped', () => {
    const without = createRegistry(NODE_TYPES.filter((t) => t.type !== 'seed-image'));
    const r = importFlower(withMirror({ cornerX: 0, cornerY: 0, width: 1, height: 1 }), without);
    if (!r.ok) throw new Error('import failed');
    expect(r.doc.nodes.some((n) => n.type === 'seed-image')).toBe(false);
    expect(messages(r.notes)).toEqual([expect.stringMatching(/OrbitSeed "os" cannot be mapped yet/)]);
  });
});
