import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Scene } from '../../../nodes/core/scene.ts';
import type { Vec2 } from '../../../nodes/core/values.ts';
import type { IisState } from '../../../shader-gen/elements/element-kind.ts';
import { farDisk, farDistance, limitReach } from '../../../shader-gen/far-disk.ts';
import { limitSetDfs } from '../../../shader-gen/figures/limit-dfs.ts';
import { prepare, runIis } from '../../../shader-gen/interpret.ts';
import { loadExample } from '../../support/examples.ts';

const SIZE = 400;
const options = (scene: Scene) => ({ pixelWorld: scene.view.scale / SIZE, width: SIZE, height: SIZE });

/**
 * The glow's distance to the limit set at p, in pixels (raster.ts sampleColour's limit-set
 * estimate: (edge distance + reach)/s at the end of the IIS run), or 0 when the run never reaches
 * the tile (the glow paints such a point in the limit colour).
 */
function glowPixels(scene: Scene, p: Vec2, maxIterations: number): number {
  const prepared = prepare(scene.elements);
  const st: IisState = { x: p[0], y: p[1], s: 1, depth: 0 };
  if (!runIis(prepared, maxIterations, st)) return 0;
  let d = Number.POSITIVE_INFINITY;
  for (let i = 0; i < prepared.elements.length; i++)
    d = Math.min(d, prepared.kinds[i].boundaryDistance(prepared.elements[i], st.x, st.y));
  const far = farDisk(scene.elements);
  if (far) d = Math.max(d, farDistance(far, st.x, st.y));
  return (d + (limitReach(scene.elements) ?? 0)) / st.s / options(scene).pixelWorld;
}

describe('limit set by depth-first search', () => {
  // Inversions (Fig. 5), a two-circle Möbius pair and matrix generators: every point the search
  // writes is where the glow of the same group says the limit set is, to within two pixels.
  for (const name of ['fig05-limit-set', 'schottky-pair', 'schottky-matrix-generators']) {
    it(`every point of ${name} lies on the glow's limit set`, () => {
      const { scene } = loadExample(name);
      const r = limitSetDfs(scene, options(scene));
      if (!r.ok) throw new Error(r.message);
      expect(r.capped).toBeUndefined();
      const points = r.curves.flat();
      expect(points.length).toBe(r.leaves);
      expect(points.length).toBeGreaterThan(100);
      fc.assert(
        fc.property(fc.integer({ min: 0, max: points.length - 1 }), (i) => {
          expect(glowPixels(scene, points[i], 1000)).toBeLessThan(2);
        }),
        { seed: 42, numRuns: 200 },
      );
    });
  }

  it('finds nothing where the glow sees no limit set: every pixel centre far from the points is lit dark', () => {
    const { scene } = loadExample('fig05-limit-set');
    const r = limitSetDfs(scene, options(scene));
    if (!r.ok) throw new Error(r.message);
    const points = r.curves.flat();
    const px = options(scene).pixelWorld;
    let checked = 0;
    for (let i = 0; i < SIZE; i += 10) {
      for (let j = 0; j < SIZE; j += 10) {
        const p: Vec2 = [
          scene.view.center[0] + (i - SIZE / 2) * px,
          scene.view.center[1] + (j - SIZE / 2) * px,
        ];
        const near = points.some((q) => Math.hypot(p[0] - q[0], p[1] - q[1]) < 8 * px);
        if (near) continue;
        checked++;
        // The glow's estimate is a bound, not the distance: away from the points it is above a pixel.
        expect(glowPixels(scene, p, 1000)).toBeGreaterThan(1);
      }
    }
    expect(checked).toBeGreaterThan(1000);
  });

  it('joins neighbouring points into curves when the disks touch (a circle of kissing disks)', () => {
    const { scene } = loadExample('fig02-four-kissing-disks');
    const r = limitSetDfs(scene, options(scene));
    if (!r.ok) throw new Error(r.message);
    const longest = Math.max(...r.curves.map((c) => c.length));
    expect(longest).toBeGreaterThan(50);
  });

  it('refuses groups that are not Schottky-type, naming the node, and stops at the word cap', () => {
    const overlap = limitSetDfs(
      loadExample('fig08-hyperbolic-tessellation').scene,
      options(loadExample('fig08-hyperbolic-tessellation').scene),
    );
    expect(overlap.ok).toBe(false);
    if (!overlap.ok) expect(overlap.message).toMatch(/acts outside a bounded disk/);
    const { scene } = loadExample('fig05-limit-set');
    const moved = {
      ...scene,
      elements: scene.elements.map((e, i) =>
        i === 0 && e.kind === 'inversion' ? { ...e, r: e.r * 1.5 } : e,
      ),
    };
    const clash = limitSetDfs(moved, options(scene));
    expect(clash.ok).toBe(false);
    if (!clash.ok)
      expect(clash.message).toMatch(/overlap: the depth-first search draws Schottky-type groups/);
    const capped = limitSetDfs(scene, { ...options(scene), maxWords: 500 });
    expect(capped.ok && capped.capped).toMatch(/stopped at 500 words/);
  });
});
