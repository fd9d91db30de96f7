/**
 * The CPU sphere tracer (shader-gen/space/trace-3d.ts, docs/math-3d.md "§9 The sphere tracer: march, hit, shading"): a lone sphere seen
 * head-on is hit where the geometry says and missed just outside; a mirror-symmetric scene gives
 * a mirror-symmetric image; inversion spheres stay invisible — only the orbit is drawn — and the
 * traced image of Fig. 11 matches a brute-force ray cast of its enumerated orbit spheres (the
 * tracer misses no sphere the ray cast sees, and draws none it does not).
 */
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import type { Sphere } from '../../../nodes/geometry/space/sphere.ts';
import { cameraBasis, pixelAngle, rayDirection } from '../../../shader-gen/space/camera-3d.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { probeScene3d, renderScene3d } from '../../../shader-gen/space/render-3d.ts';
import { traceRay } from '../../../shader-gen/space/trace-3d.ts';
import { bruteRayHit, inversionOrbit } from './orbit-brute-force.ts';
import { FIG11, LONE_SPHERE, scene3d, seedSphere, sixSpheres } from './scenes-3d.ts';

/** Points half a pixel from a pixel's centre (and the centre's corners): a silhouette there may move. */
const NEIGHBOURS: readonly (readonly [number, number])[] = [
  [0, 0.5],
  [1, 0.5],
  [0.5, 0],
  [0.5, 1],
  [0.15, 0.15],
  [0.85, 0.15],
  [0.15, 0.85],
  [0.85, 0.85],
];

const W = 100;
const H = 100;

function rayAt(scene: Scene3d, px: number, py: number, w = W, h = H) {
  const b = cameraBasis(scene.camera);
  return { o: b.origin, d: rayDirection(b, w, h, px, py), angle: pixelAngle(b, h) };
}

describe('CPU sphere tracer', () => {
  const plan = prepareTrace3d(LONE_SPHERE);

  it('hits a lone sphere head-on at the distance the geometry gives', () => {
    const { o, d, angle } = rayAt(LONE_SPHERE, W / 2, H / 2);
    const hit = traceRay(plan, o, d, angle);
    expect(hit.hit).toBe(true);
    expect(hit.depth).toBe(0);
    expect(hit.seed).toBe(0);
    // Camera 5 from the centre, radius 1: the surface is at t = 4, found within the tolerance.
    expect(Math.abs(hit.t - 4)).toBeLessThan(0.5 * angle * 4 + 1e-9);
  });

  it('draws the sphere to its silhouette: hit just inside, miss just outside', () => {
    const { angle } = rayAt(LONE_SPHERE, 0, 0);
    // Angular radius asin(1/5); on the image plane tan(asin(1/5))/angle pixels from the centre.
    const edge = Math.tan(Math.asin(1 / 5)) / angle;
    for (const [dx, dy] of [
      [1, 0],
      [0, 1],
      [-0.6, 0.8],
    ]) {
      const at = (f: number) => {
        const { o, d } = rayAt(LONE_SPHERE, W / 2 + dx! * edge * f, H / 2 + dy! * edge * f);
        return traceRay(plan, o, d, angle).hit;
      };
      expect(at(0.97)).toBe(true);
      expect(at(1.03)).toBe(false);
    }
  });

  it('gives a mirror-symmetric image of a mirror-symmetric scene (Fig. 11 seen along y)', () => {
    const scene: Scene3d = { ...FIG11, camera: { position: [0, -6, 0.8], target: [0, 0, 0], fovDeg: 45 } };
    const w = 48;
    const h = 36;
    const probe = probeScene3d(scene, w, h);
    let hits = 0;
    let asymmetric = 0;
    for (let py = 0; py < h; py++) {
      for (let px = 0; px < w; px++) {
        const a = 4 * (py * w + px);
        const b = 4 * (py * w + (w - 1 - px));
        if (probe[a] === 1) hits++;
        if (probe[a] !== probe[b] || probe[a + 2] !== probe[b + 2]) asymmetric++;
      }
    }
    expect(hits).toBeGreaterThan(0.1 * w * h);
    expect(asymmetric).toBeLessThanOrEqual(0.01 * w * h);
  });

  it('keeps an inversion sphere invisible: rays through it hit only the orbit inside it', () => {
    // One mirror and one seed: the orbit is the seed and its single image inside the mirror.
    const mirror: Sphere = { center: [0, 0, 0], radius: 1 };
    const seed: Sphere = { center: [2.5, 0, 0], radius: 0.5 };
    const scene = scene3d(
      [{ kind: 'sphere-inversion', sphere: mirror }],
      [seedSphere(seed.center, seed.radius)],
      {
        camera: { position: [0.8, -5, 0.3], target: [0.8, 0, 0], fovDeg: 45 },
      },
    );
    const p = prepareTrace3d(scene);
    const orbit = inversionOrbit([mirror], [seed], 1);
    let throughMirror = 0;
    for (let py = 0; py < 60; py += 1) {
      for (let px = 0; px < 80; px += 1) {
        const { o, d, angle } = rayAt(scene, px + 0.5, py + 0.5, 80, 60);
        const expected = bruteRayHit(orbit, o, d) !== null;
        if (bruteRayHit([mirror], o, d) !== null && !expected) throughMirror++;
        // Silhouettes of orbit spheres may move by the hit tolerance: skip pixels within half a pixel.
        const near = NEIGHBOURS.some(
          ([fx, fy]) =>
            (bruteRayHit(orbit, o, rayAt(scene, px + fx, py + fy, 80, 60).d) !== null) !== expected,
        );
        if (!near) expect(traceRay(p, o, d, angle).hit, `pixel ${px}, ${py}`).toBe(expected);
      }
    }
    expect(throughMirror).toBeGreaterThan(300); // many rays cross the mirror ball and must miss
  });

  it('matches a brute-force ray cast of the orbit spheres of words ≤ 5 (Fig. 11)', () => {
    const mirrors = sixSpheres().map((e) => (e as { sphere: Sphere }).sphere);
    const seed = (FIG11.seeds[0] as { sphere: Sphere }).sphere;
    const orbit = inversionOrbit(mirrors, [seed], 5);
    const p = prepareTrace3d(FIG11);
    const w = 64;
    const h = 48;
    let compared = 0;
    let agree = 0;
    for (let py = 0; py < h; py++) {
      for (let px = 0; px < w; px++) {
        const { o, d, angle } = rayAt(FIG11, px + 0.5, py + 0.5, w, h);
        const expected = bruteRayHit(orbit, o, d);
        // Robust: half a pixel away the ray meets the same sphere (or misses too) — not a silhouette.
        const robust = NEIGHBOURS.every(([fx, fy]) => {
          const t = bruteRayHit(orbit, o, rayAt(FIG11, px + fx, py + fy, w, h).d);
          return expected === null ? t === null : t !== null && Math.abs(t - expected) < 0.02 * expected;
        });
        if (!robust) continue;
        compared++;
        const hit = traceRay(p, o, d, angle);
        if (hit.hit === (expected !== null) && (!hit.hit || Math.abs(hit.t - expected!) < 0.01 * expected!))
          agree++;
      }
    }
    expect(compared).toBeGreaterThan(0.85 * w * h);
    expect(agree / compared).toBeGreaterThanOrEqual(0.99);
  });

  it('renders lit, coloured spheres on the background colour', () => {
    const r = renderScene3d(LONE_SPHERE, 40, 40);
    const px = (x: number, y: number) => [...r.data.subarray(4 * (y * 40 + x), 4 * (y * 40 + x) + 4)];
    // The corner is the background (sRGB 8-bit of the scene's colour), the centre the lit seed.
    expect(px(0, 0)).toEqual([0.06, 0.07, 0.1].map((c) => Math.round(255 * c)).concat(255));
    const [r0, g0, b0] = px(20, 20);
    expect(r0!).toBeGreaterThan(g0! + 40); // the seed is orange-red, lit
    expect(r0!).toBeGreaterThan(b0! + 40);
    // The light comes from above: the top of the sphere is brighter than its bottom.
    expect(px(20, 12)[0]!).toBeGreaterThan(px(20, 28)[0]!);
  });
});
