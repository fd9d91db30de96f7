import { describe, expect, it } from 'vitest';
import type { Scene } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import { applyMap } from '../../../nodes/geometry/anti-mobius.ts';
import { autoBase, cayleyGraph } from '../../../shader-gen/figures/cayley.ts';
import { edgePath, figureLayer } from '../../../shader-gen/figures/layer.ts';
import { interpret } from '../../../shader-gen/interpret.ts';
import { loadExample } from '../../support/examples.ts';

const PX = (scene: Scene) => scene.view.scale / 800;
const far = (p: Vec2, q: Vec2) => Math.hypot(p[0] - q[0], p[1] - q[1]);

describe('Cayley graph', () => {
  it('of four kissing inversions is the 4-regular tree: 1 + 4 + 12 + 36 tiles at depth 3', () => {
    const { scene } = loadExample('fig01-cayley-graph');
    const g = cayleyGraph(scene, null, { depth: 3, pixelWorld: PX(scene) });
    if (!g.ok) throw new Error(g.message);
    expect(g.vertices).toHaveLength(53);
    expect(g.edges).toHaveLength(52);
    expect(g.generators.map((x) => x.name)).toEqual(['a', 'b', 'c', 'd']);
  });

  it('edge k from the base goes to T_k(base), and every edge is w(p₀) → w T_k(p₀) for a vertex w(p₀)', () => {
    const { scene } = loadExample('fig01-cayley-graph');
    const g = cayleyGraph(scene, null, { depth: 4, pixelWorld: PX(scene) });
    if (!g.ok) throw new Error(g.message);
    for (const e of g.edges.filter((x) => x.depth === 0)) {
      const want = applyMap(g.generators[e.generator].map, g.base);
      expect(want).not.toBeNull();
      if (want) expect(far(e.to, want)).toBeLessThan(1e-9);
    }
    const isVertex = (p: Vec2) => g.vertices.some((v) => far(v, p) < 1e-9);
    for (const e of g.edges) expect(isVertex(e.from) && isVertex(e.to)).toBe(true);
  });

  // The IIS folds the centre w(p₀) of the tile w(F) back to p₀: the vertices are tile centres. To
  // a tenth of a pixel: graphs from rounded coordinates are only nearly discrete groups.
  for (const name of [
    'fig01-cayley-graph',
    'fig08-hyperbolic-tessellation',
    'kaleidoscope-333',
    'schottky-pair',
  ]) {
    it(`every vertex of ${name} is a tile centre: the IIS maps it to the base point`, () => {
      const { scene } = loadExample(name);
      const g = cayleyGraph(scene, null, { depth: 4, pixelWorld: PX(scene) });
      if (!g.ok) throw new Error(g.message);
      expect(g.vertices.length).toBeGreaterThan(10);
      for (const v of g.vertices) {
        const r = interpret({ elements: scene.elements, maxIterations: 200 }, v);
        expect(r.escaped).toBe(true);
        expect(far(r.final, g.base)).toBeLessThan(PX(scene) / 10);
      }
    });
  }

  it('the automatic base point lies in the fundamental tile, in the hole of the ring of disks', () => {
    const { scene } = loadExample('fig01-cayley-graph');
    const base = autoBase(scene);
    expect(base).not.toBeNull();
    if (!base) return;
    expect(interpret({ elements: scene.elements, maxIterations: 1 }, base).depth).toBe(0);
    expect(far(base, scene.view.center)).toBeLessThan(0.3);
  });

  it('keeps its vertices on their tiles while the view pans: the base point comes from the document’s view', () => {
    const { scene } = loadExample('fig01-cayley-graph');
    const panned = {
      ...scene,
      view: { ...scene.view, center: [scene.view.center[0] + 0.11, scene.view.center[1] - 0.07] as Vec2 },
    };
    const vertices = (layer: ReturnType<typeof figureLayer>) => layer.strokes.map((s) => s.points[0]);
    const still = vertices(figureLayer(scene, 800, 600));
    // Drawn at the panned view with the base chosen in the document's view: the same graph.
    expect(vertices(figureLayer(panned, 800, 600, scene.view)).slice(0, 4)).toEqual(still.slice(0, 4));
    // Chosen in the panned view itself, the base moves with it (what the overlay did before).
    expect(vertices(figureLayer(panned, 800, 600)).slice(0, 4)).not.toEqual(still.slice(0, 4));
  });

  it('says which node it cannot take, and stops at the edge cap with a message', () => {
    const { scene } = loadExample('fig41-maskit-limit-set');
    const g = cayleyGraph(scene, null, { depth: 3, pixelWorld: PX(scene) });
    expect(g.ok).toBe(false);
    if (!g.ok) expect(g.message).toMatch(/Maskit group: the Cayley graph and the depth-first limit set take/);
    const { scene: tree } = loadExample('fig01-cayley-graph');
    const capped = cayleyGraph(tree, null, { depth: 6, pixelWorld: PX(tree), maxEdges: 20 });
    expect(capped.ok && capped.capped).toMatch(/stopped at 20 edges/);
  });

  it('draws an edge of the Poincaré disk as a geodesic: an arc orthogonal to the rim', () => {
    const clip = { c: [0, 0] as Vec2, r: 1 };
    const path = edgePath([0.2, 0.1], [-0.3, 0.5], clip);
    expect(path.length).toBeGreaterThan(2);
    // The circle through three of its points meets the unit circle at right angles: |c|² = r² + 1.
    const [a, b, c] = [path[0], path[5], path[path.length - 1]];
    const d = 2 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    const bb = (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2;
    const cc = (c[0] - a[0]) ** 2 + (c[1] - a[1]) ** 2;
    const centre = [
      a[0] + ((c[1] - a[1]) * bb - (b[1] - a[1]) * cc) / d,
      a[1] + ((b[0] - a[0]) * cc - (c[0] - a[0]) * bb) / d,
    ];
    const r2 = (centre[0] - a[0]) ** 2 + (centre[1] - a[1]) ** 2;
    expect(Math.abs(centre[0] ** 2 + centre[1] ** 2 - r2 - 1)).toBeLessThan(1e-9);
    expect(edgePath([0.2, 0.1], [-0.3, 0.5], null)).toHaveLength(2);
    // Through the centre of the disk the geodesic is straight.
    expect(edgePath([0.2, 0.2], [-0.4, -0.4], clip)).toHaveLength(2);
  });
});
