/**
 * The tracer's bound stays safe with a formula seed (docs/formula.md "3D seed shapes",
 * nodes/formula/solid.ts): in Fig. 11 set-ups with a torus seed of random size and tilt, the walk's
 * bound at points inside the mirrors never exceeds the distance to brute-force images of points on
 * the torus (words of length ≤ 3: a finite part of the orbit's closure, so never below the true
 * distance), and the seed's own distance is never above the distance to the torus points.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Element3d, Seed3d } from '../../../nodes/core/scene-3d.ts';
import type { Sphere } from '../../../nodes/geometry/space/sphere.ts';
import { add3, scale3, type Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { seedDistance } from '../../../shader-gen/space/seeds-3d.ts';
import { walk3d } from '../../../shader-gen/space/walk.ts';
import { real, SEED, unit3 } from '../../nodes/geometry/space/arbitraries.ts';
import { AXES, scene3d } from './scenes-3d.ts';

const TORUS_TILTED =
  'length(point(length(point(x, rotate(point(y, z), c).x)) - a, rotate(point(y, z), c).y)) - b';

/** x ↦ c + r²(x − c)/|x − c|², the inversion in the sphere. */
function invert(m: Sphere, x: Vec3): Vec3 {
  const d: Vec3 = [x[0] - m.center[0], x[1] - m.center[1], x[2] - m.center[2]];
  const k = (m.radius * m.radius) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return [m.center[0] + k * d[0], m.center[1] + k * d[1], m.center[2] + k * d[2]];
}

/** Points of the tilted torus's surface: (R + r cos v)(cos u, sin u), r sin v, (y, z) turned by −c. */
function torusPoints(R: number, r: number, c: number, n: number): Vec3[] {
  const out: Vec3[] = [];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++) {
      const u = (2 * Math.PI * i) / n;
      const v = (2 * Math.PI * j) / n;
      const x = (R + r * Math.cos(v)) * Math.cos(u);
      const y = (R + r * Math.cos(v)) * Math.sin(u);
      const z = r * Math.sin(v);
      // rotate(point(y, z), c) maps the body frame to the torus frame; the body is its inverse
      out.push([x, Math.cos(c) * y + Math.sin(c) * z, -Math.sin(c) * y + Math.cos(c) * z]);
    }
  return out;
}

/** The images of `points` under reduced words of length ≤ n in the inversions. */
function orbitPoints(mirrors: readonly Sphere[], points: readonly Vec3[], n: number): Vec3[] {
  const all = [...points];
  let level = points.map((p) => ({ p, last: -1 }));
  for (let k = 0; k < n; k++) {
    const next: { p: Vec3; last: number }[] = [];
    for (const { p, last } of level)
      mirrors.forEach((m, i) => {
        if (i !== last) next.push({ p: invert(m, p), last: i });
      });
    all.push(...next.map((e) => e.p));
    level = next;
  }
  return all;
}

function nearest(pts: readonly Vec3[], x: Vec3): number {
  let best = Number.POSITIVE_INFINITY;
  for (const p of pts) best = Math.min(best, Math.hypot(p[0] - x[0], p[1] - x[1], p[2] - x[2]));
  return best;
}

const setup = fc.record({
  // R + r < 0.288: the torus stays inside the seed's bounding ball of radius 0.29
  R: real(0.1, 0.18),
  rf: real(0.2, 0.6),
  c: real(-1.5, 1.5),
  mirror: fc.integer({ min: 0, max: 5 }),
  dir: unit3,
  t: real(0, 1),
});

describe('the tracer bound with a formula seed (a tilted torus)', () => {
  it('never exceeds the distance to the images of the torus under words ≤ 3', () => {
    let moved = 0;
    fc.assert(
      fc.property(setup, ({ R, rf, c, mirror, dir, t }) => {
        const r = rf * R;
        const mirrors: Sphere[] = AXES.map((e) => ({ center: e, radius: 0.7 }));
        const seed: Seed3d = {
          kind: 'formula',
          nodeId: 'torus',
          center: [0, 0, 0],
          radius: 0.29,
          formula: TORUS_TILTED,
          numbers: [R, r, c],
          slope: 1,
          color: [1, 0.7, 0.3],
        };
        const elements: Element3d[] = mirrors.map((sphere) => ({ kind: 'sphere-inversion', sphere }));
        const plan = prepareTrace3d(scene3d(elements, [seed]));
        const m = mirrors[mirror]!;
        const x = add3(m.center, scale3(dir, t * m.radius));
        const w = walk3d(plan, ...x, true);
        if (w.depth > 0) moved++;
        const brute = nearest(orbitPoints(mirrors, torusPoints(R, r, c, 16), 3), x);
        expect(w.de).toBeGreaterThanOrEqual(0);
        expect(w.de).toBeLessThanOrEqual(brute * (1 + 1e-9) + 1e-12);
        // the seed's own bound at x (outside its ball here) is no more than the torus points' distance
        expect(seedDistance(seed, ...x)).toBeLessThanOrEqual(nearest(torusPoints(R, r, c, 16), x) + 1e-12);
      }),
      { ...SEED, numRuns: 80 },
    );
    expect(moved).toBeGreaterThan(40);
  }, 120_000);
});
