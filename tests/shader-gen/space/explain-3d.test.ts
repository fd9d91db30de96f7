/**
 * "Explain this pixel" in 3D (shader-gen/space/explain-3d.ts): a pixel on the Fig. 11 orbit is
 * explained by the tracer's own hit and depth, its word maps the hit point onto the seed sphere
 * (the final point lies on the seed's surface) step by step with growing depth and the factors of
 * the inversions; a pixel looking past the orbit is a miss with an empty word.
 */
import { describe, expect, it } from 'vitest';
import { iis3d } from '../../../nodes/geometry/space/iis-3d.ts';
import { explainPixel3d } from '../../../shader-gen/space/explain-3d.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { tracePixel } from '../../../shader-gen/space/render-3d.ts';
import { exampleScenes3d, FIG11 } from './scenes-3d.ts';

const W = 64;
const H = 64;
const dist = (a: readonly number[], b: readonly number[]) => Math.hypot(...a.map((v, i) => v - b[i]!));

/** The image points of a W × H picture whose rays hit, with depth > 0 (an image of the seed). */
function hitPixels(scene: typeof FIG11) {
  const plan = prepareTrace3d(scene);
  const out: [number, number][] = [];
  for (let py = 0.5; py < H; py += 4)
    for (let px = 0.5; px < W; px += 4) {
      const { hit } = tracePixel(plan, W, H, px, py);
      if (hit.hit && hit.depth > 0) out.push([px, py]);
    }
  return out;
}

describe('explainPixel3d', () => {
  const seed = FIG11.seeds[0]!;
  if (seed.kind !== 'sphere') throw new Error('Fig. 11 has a seed sphere');
  const pixels = hitPixels(FIG11);

  it('finds orbit pixels to explain', () => expect(pixels.length).toBeGreaterThan(10));

  it('agrees with the tracer and maps the hit point onto the seed sphere, step by step', () => {
    const plan = prepareTrace3d(FIG11);
    for (const [px, py] of pixels) {
      const e = explainPixel3d(FIG11, W, H, px, py);
      const { hit } = tracePixel(plan, W, H, px, py);
      expect(e.stop).toBe('seed');
      expect(e.seed).toBe(hit.seed);
      expect(e.t).toBe(hit.t);
      expect(e.depth).toBe(hit.depth);
      expect(e.steps.map((s) => s.depth)).toEqual(e.steps.map((_, i) => i + 1));
      // the run of the word is the IIS loop's own: same final point and factor
      const run = iis3d(FIG11.elements, e.start, FIG11.maxIterations);
      expect(e.final).toEqual(run.point);
      expect(e.scale).toBe(run.factor);
      expect(e.steps.at(-1)!.at).toEqual(e.final);
      // the hit point lies on an image of the seed: its final point on the seed's surface (within
      // the hit tolerance, a quarter pixel, scaled up by the inversions' factor)
      const off = Math.abs(dist(e.final, seed.sphere.center) - seed.sphere.radius);
      expect(off).toBeLessThan(0.05 * Math.max(1, e.scale));
      // each inversion shrinks or grows by r²/|x − c|²: the factors are products, never zero
      for (const s of e.steps) expect(s.factor).toBeGreaterThan(0);
    }
  });

  it('a pixel looking past the orbit is a miss with an empty word', () => {
    const sky = { ...FIG11, camera: { ...FIG11.camera, target: [0, 0, 40] as [number, number, number] } };
    const e = explainPixel3d(sky, W, H, W / 2, H - 1);
    expect(e.stop).toBe('missed');
    expect(e.steps).toEqual([]);
    expect(e.seed).toBe(-1);
  });

  it('names the node of every step on the examples (elements carry their node ids)', () => {
    const scene = exampleScenes3d()['fig11-sphere-inversion-fractal']!;
    const ids = new Set(scene.elements.map((el) => (el as { nodeId?: string }).nodeId));
    const [px, py] = hitPixels(scene)[0]!;
    const e = explainPixel3d(scene, W, H, px, py);
    expect(e.steps.length).toBeGreaterThan(0);
    for (const s of e.steps) expect(ids.has(s.nodeId) && s.nodeId !== '').toBe(true);
  });
});
