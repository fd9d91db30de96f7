import { describe, expect, it } from 'vitest';
import { createRegistry } from '../../../../nodes/core/registry.ts';
import type { TileSpec } from '../../../../nodes/core/scene.ts';
import { registry } from '../../../../nodes/types/index.ts';
import { pointNode } from '../../../../nodes/types/point.ts';
import { type DepthColoring, depthColour, hsvToRgb } from '../../../../shader-gen/colour.ts';
import { sampleColour, sampleContext } from '../../../../shader-gen/raster.ts';
import { toLinear } from '../../../../shader-gen/srgb.ts';
import { FLOWER_RENDER, importFlower, isFlowerDocument } from '../../../../src/io/flower/import.ts';
import { fedge, fnode, fpoint, graph, lineMirror } from './support/flower-fixture.ts';
import { imported, messages } from './support/imported.ts';

describe('Flower import: recognising the format', () => {
  it('recognises Flower graphs by shape and nothing else', () => {
    expect(isFlowerDocument(graph(lineMirror('m', [0, 0], [1, 0], false)))).toBe(true);
    expect(isFlowerDocument({ format: 'kleinflow', nodes: [], edges: [] })).toBe(false);
    expect(isFlowerDocument({ nodes: [{ name: 'Point' }] })).toBe(false);
    expect(isFlowerDocument([])).toBe(false);
    const r = importFlower({ hello: 'world' });
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.diagnostics[0].code).toBe('KF501');
  });
});

describe('Flower import: colours, notes and view', () => {
  it("tile reproduces Flower's colours: hue 0.01 + 0.05(n − 1) after n reflections", () => {
    const { scene } = imported(graph(lineMirror('m', [0, 0], [1, 0], false)));
    const tile = scene.tile as TileSpec;
    expect(tile.coloring.mode).toBe('depth-hsv');
    for (let n = 1; n <= FLOWER_RENDER.maxIterations; n++) {
      const flower = hsvToRgb(0.01 + 0.05 * (n - 1), 1, 1);
      const ours = depthColour(tile.coloring as DepthColoring, n);
      for (let k = 0; k < 3; k++) expect(ours[k]).toBeCloseTo(flower[k], 9);
    }
    expect(scene.maxIterations).toBe(50);
    expect(scene.samples).toBe(20);
  });

  it('the tile itself (depth 0) is black, as Flower leaves it uncoloured; deeper points keep their hue', () => {
    const { scene } = imported(graph(lineMirror('m', [0, 0], [1, 0], false)));
    expect(scene.tile.fill).toEqual([0, 0, 0]);
    const pixel = (y: number) =>
      sampleColour(scene, sampleContext(scene), 0.3, y, 0.01, { x: 0, y: 0, s: 1, depth: 0 });
    const [kept, mirrored] = [pixel(0.4), pixel(-0.4)];
    const one = scene.maxIterations > 0 ? depthColour(scene.tile.coloring as DepthColoring, 1) : null;
    // One side of the mirror is the tile (black), the other its image at depth 1 (Flower's first hue).
    const black = [kept, mirrored].filter((c) => c.every((v) => v === 0));
    expect(black).toHaveLength(1);
    const other = kept === black[0] ? mirrored : kept;
    expect(other).toEqual(toLinear(one!));
  });

  it('ColorPalettes with Vec3 inputs becomes the tile palette, matching Flower at every depth', () => {
    const vec = (id: string, v: number[]) => fnode('Vec3', id, { valueX: v[0], valueY: v[1], valueZ: v[2] });
    const [a, b, c, d] = [
      [0.5, 0.5, 0.5],
      [0.5, 0.5, 0.5],
      [1, 1, 1],
      [0, 0.33, 0.67],
    ];
    const json = graph(lineMirror('m', [0, 0], [1, 0], false), {
      nodes: [vec('va', a), vec('vb', b), vec('vc', c), vec('vd', d), fnode('ColorPalettes', 'pal')],
      edges: ['va', 'vb', 'vc', 'vd'].map((v, i) => fedge('Vec3', v, 'pal', i)),
    });
    const { scene, notes } = imported(json);
    expect(notes).toEqual([]);
    expect(scene.tile.coloring.mode).toBe('cosine');
    for (let n = 1; n <= 20; n++) {
      const ours = depthColour(scene.tile.coloring as DepthColoring, n);
      for (let k = 0; k < 3; k++) {
        const flower = a[k] + b[k] * Math.cos(2 * Math.PI * (c[k] * 0.05 * (n - 1) + d[k]));
        expect(Math.abs(ours[k] - Math.min(1, Math.max(0, flower)))).toBeLessThan(0.02); // colours are stored as 8-bit
      }
    }
  });

  it('a palette that cannot be read, or a Vec3 used elsewhere, is reported', () => {
    const json = graph(lineMirror('m', [0, 0], [1, 0], false), {
      nodes: [fnode('Vec3', 'v', { valueX: 1, valueY: 0, valueZ: 0 }), fnode('ColorPalettes', 'pal')],
      edges: [fedge('Vec3', 'v', 'pal', 0)],
    });
    const { scene, notes } = imported(json);
    expect(messages(notes)).toEqual([
      expect.stringMatching(/palette vector b could not be read; Flower's rainbow colouring is used/),
    ]);
    expect(scene.tile.coloring.mode).toBe('depth-hsv');
    const lone = imported(graph({ nodes: [fnode('Vec3', 'v')], edges: [] }));
    expect(messages(lone.notes)).toEqual([expect.stringMatching(/Vec3 "v" cannot be mapped/)]);
  });

  it('tolerates duplicated node entries; a duplicate with different data gets a note', () => {
    const base = lineMirror('m', [0, 0], [1, 0], false);
    const same = graph({ nodes: [...base.nodes, base.nodes[2], base.nodes[3]], edges: base.edges });
    const r1 = imported(same);
    expect(r1.notes).toEqual([]);
    expect(r1.doc.nodes.filter((n) => n.type === 'line')).toHaveLength(1);
    const different = graph({ nodes: [...base.nodes, { ...base.nodes[0], posX: 99 }], edges: base.edges });
    const r2 = imported(different);
    expect(messages(r2.notes)).toEqual([
      expect.stringMatching(/node "ma" appears again with different data/),
    ]);
    expect(r2.doc.nodes.find((n) => n.type === 'point')!.params).toEqual({ x: 0, y: 0 });
  });

  it('reports what cannot be mapped: unknown types, broken and mistyped edges, mirrors with nothing wired', () => {
    const json = graph(lineMirror('m', [0, 0], [1, 0], false), {
      nodes: [
        fnode('Spiral', 'sp'),
        fnode('LineMirror', 'lonely', { reverse: false }),
        fnode('CircleMirror', 'lonelyC'),
        fpoint('q', 0, 0),
      ],
      edges: [
        { id: 'x1', name: 'Point', s1Id: 'nowhere', s2Id: 'm-in0' },
        { id: 'x2', name: 'Point', s1Id: 'ma-out0', s2Id: 'q-out0' },
        { id: 'x3', name: 'Point', s1Id: 'q-out0', s2Id: 'lonelyC-in0' },
      ],
    });
    const { notes, scene, errors } = imported(json);
    expect(errors).toEqual([]);
    const text = messages(notes);
    expect(text).toEqual(
      expect.arrayContaining([
        expect.stringMatching(/unknown Flower node type "Spiral"/),
        expect.stringMatching(/names socket "nowhere", which no node has/),
        expect.stringMatching(/joins two outputs/),
        expect.stringMatching(/joins a Point output to a Circle input/),
        expect.stringMatching(/LineMirror "lonely" has no line wired in/),
        expect.stringMatching(/CircleMirror "lonelyC" has no circle wired in/),
      ]),
    );
    for (const n of notes) expect(n.code).toBe('KF502');
    expect(scene.elements).toHaveLength(1);
  });

  it("opens on Flower's view (origin, 100 units tall), larger when the construction reaches further", () => {
    expect(imported(graph(lineMirror('m', [0, 0], [1, 0], false))).doc.view).toEqual({
      center: [0, 0],
      scale: 100,
    });
    expect(imported(graph(lineMirror('m', [0, 0], [80, 0], false))).doc.view).toEqual({
      center: [0, 0],
      scale: 176,
    });
  });
});

describe('Flower import: node versions', () => {
  it('imported nodes are current: a type at a later version does not migrate them as if they were old', () => {
    // A point type at version 2 whose (made-up) migration would drop v1 params: the import writes
    // today's params, so it must mark its nodes current and loading must leave them alone.
    const point2 = { ...pointNode, version: 2, migrations: { 1: () => ({}) } };
    const reg = createRegistry(registry.all.map((d) => (d.type === 'point' ? point2 : d)));
    const r = importFlower(graph(lineMirror('m', [0.25, 0], [1, 0.5], false)), reg);
    if (!r.ok) throw new Error(r.diagnostics.map((d) => d.message).join('; '));
    const points = r.doc.nodes.filter((n) => n.type === 'point');
    expect(points.map((n) => [n.version, n.params.x, n.params.y])).toEqual([
      [2, 0.25, 0],
      [2, 1, 0.5],
    ]);
  });
});
