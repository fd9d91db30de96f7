/**
 * The depth-first limit set of a quaternion Kleinian group (docs/math-3d.md "Quaternion Kleinian
 * groups"): its points are a limit set (each generator maps them near computed points), its caps
 * say so, and its dots sit where the tracer's camera sees the points.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { LimitSet3d } from '../../../nodes/core/limit-set-3d.ts';
import { type Camera3d, DEFAULT_LIGHTING_3D, type Scene3d } from '../../../nodes/core/scene-3d.ts';
import { mobiusQ, qmInverse, sakugawaGenerators } from '../../../nodes/geometry/space/quaternion-mobius.ts';
import { add3, dist3, scale3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { cameraBasis, pixelAngle, rayDirection } from '../../../shader-gen/space/camera-3d.ts';
import { limitSetSearch3d } from '../../../shader-gen/space/limit-dfs-3d.ts';
import { limitDots3d, paintLimitDots3d, projectPoint3d } from '../../../shader-gen/space/limit-dots-3d.ts';

const SEED = { seed: 6, numRuns: 60 };
const camera: Camera3d = { position: [1.5, -2.5, 1.6], target: [0, 0, 0], fovDeg: 40 };
const group = (more: Partial<LimitSet3d> = {}): LimitSet3d => ({
  nodeId: 'q',
  generators: sakugawaGenerators(-2, 0.3, 0.3),
  leafPx: 1.5,
  dotPx: 1,
  maxDepth: 60,
  maxWords: 1_000_000,
  colors: [
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
    [1, 1, 0],
  ],
  ...more,
});

/** Nearest-point lookup on a grid of cell size h. */
function grid(points: readonly Vec3[], h: number) {
  const cells = new Map<string, Vec3[]>();
  const key = (p: Vec3, d: readonly number[] = [0, 0, 0]) =>
    p.map((v, i) => Math.floor(v / h) + d[i]!).join();
  for (const p of points) cells.set(key(p), [...(cells.get(key(p)) ?? []), p]);
  return (p: Vec3): number => {
    let best = Number.POSITIVE_INFINITY;
    for (let dx = -1; dx <= 1; dx++)
      for (let dy = -1; dy <= 1; dy++)
        for (let dz = -1; dz <= 1; dz++)
          for (const q of cells.get(key(p, [dx, dy, dz])) ?? []) best = Math.min(best, dist3(p, q));
    return best;
  };
}

describe('the limit set of a quaternion Kleinian group by depth-first search', () => {
  const W = 240;
  const found = limitSetSearch3d(group(), camera, W, W);
  const points = found.points.map((p) => p.at);

  it('finds thousands of limit points, spread through space (not in one plane)', () => {
    expect(found.capped).toBeUndefined();
    expect(points.length).toBeGreaterThan(3000);
    // The twist lifts the points out of the plane x₃ = 0 (the paper's "three-dimensional torsion").
    const zs = points.map((p) => p[2]);
    expect(Math.max(...zs) - Math.min(...zs)).toBeGreaterThan(0.5);
    const ys = points.map((p) => p[1]);
    expect(Math.max(...ys) - Math.min(...ys)).toBeGreaterThan(0.5);
  });

  it('is invariant: each generator and inverse maps limit points near limit points', () => {
    const eps = pixelAngle(cameraBasis(camera), W) * 1.5 * dist3(camera.position, camera.target);
    const nearest = grid(points, 10 * eps);
    const [a, b] = sakugawaGenerators(-2, 0.3, 0.3);
    for (const g of [a, b, qmInverse(a), qmInverse(b)]) {
      let checked = 0;
      let near = 0;
      for (let i = 0; i < points.length; i += 7) {
        const image = mobiusQ(g, points[i]!);
        // Only images well inside the searched region (the search drops what lies far outside the view).
        if (!image || dist3(image, camera.target) > 1.2) continue;
        checked++;
        // Within 3 ε: all of them here; for a group twisted by 0.45 instead of 0.3, about 60 %.
        if (nearest(image) < 3 * eps) near++;
      }
      expect(checked).toBeGreaterThan(50);
      expect(near / checked).toBeGreaterThan(0.99);
    }
  });

  it('a point off the limit set is not near it (the invariance check can fail)', () => {
    const eps = pixelAngle(cameraBasis(camera), W) * 1.5 * dist3(camera.position, camera.target);
    const nearest = grid(points, 10 * eps);
    expect(nearest([0.05, 0.7, 0.9])).toBeGreaterThan(10 * eps);
  });

  it('says when the word cap or the depth cap stopped it', () => {
    expect(limitSetSearch3d(group({ maxWords: 500 }), camera, W, W).capped).toMatch(/stopped at 500 words/);
    expect(limitSetSearch3d(group({ maxDepth: 4 }), camera, W, W).capped).toMatch(/reached 4 letters/);
  });

  it('projects a point where the tracer’s ray through that pixel goes', () => {
    const basis = cameraBasis(camera);
    fc.assert(
      fc.property(
        fc.double({ min: 0, max: 320, noNaN: true }),
        fc.double({ min: 0, max: 200, noNaN: true }),
        fc.double({ min: 0.1, max: 50, noNaN: true }),
        (px, py, t) => {
          const p = add3(camera.position, scale3(rayDirection(basis, 320, 200, px, py), t));
          const q = projectPoint3d(basis, 320, 200, p)!;
          expect(q.x).toBeCloseTo(px, 6);
          expect(q.yUp).toBeCloseTo(py, 6);
        },
      ),
      SEED,
    );
    expect(projectPoint3d(basis, 320, 200, add3(camera.position, scale3(basis.forward, -1)))).toBeNull();
  });

  it('paints depth-sorted, lit dots: far first, near ones on top', () => {
    const scene = { camera, lighting: DEFAULT_LIGHTING_3D, limitSets: [group()] } as unknown as Scene3d;
    const { dots } = limitDots3d(scene, 160, 160);
    expect(dots.length).toBeGreaterThan(1000);
    for (let i = 1; i < dots.length; i++) expect(dots[i]!.depth).toBeLessThanOrEqual(dots[i - 1]!.depth);
    const data = new Uint8ClampedArray(160 * 160 * 4);
    paintLimitDots3d(scene, dots, 160, 160, data);
    const inside = dots.filter((d) => d.x > 3 && d.x < 157 && d.y > 3 && d.y < 157);
    const last = inside[inside.length - 1]!;
    const o = 4 * (Math.floor(last.y) * 160 + Math.floor(last.x));
    // The nearest dot in the picture is on top: its centre pixel is opaque and of its own colour.
    expect(data[o + 3]).toBeGreaterThan(0);
    const lit = [0, 1, 2].map((k) => data[o + k]!);
    const colour = last.color.map((c) => c > 0.5);
    for (let k = 0; k < 3; k++) if (!colour[k]) expect(lit[k]).toBeLessThan(lit[colour.indexOf(true)]!);
  });
});
