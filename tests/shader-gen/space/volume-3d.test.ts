/**
 * The CPU volume renderer (shader-gen/space/volume-3d.ts, docs/math-3d.md "§11 Volume rendering of
 * the nesting depth"): no mirrors draw the background; one mirror's optical depth is density × its
 * chord; a point nested inside one more mirror image has one more depth and at least as much
 * extinction; the compositing keeps T = e^(−τ) and stops once the ray is opaque; the pixel offset is
 * deterministic and spread over [0, 1).
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Sphere, Vec3 } from '../../../nodes/core/scene-3d.ts';
import { invertInSphere } from '../../../nodes/geometry/space/sphere.ts';
import { cameraBasis, rayDirection } from '../../../shader-gen/space/camera-3d.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { renderScene3d } from '../../../shader-gen/space/render-3d.ts';
import {
  EXIT_TRANSMITTANCE,
  extinction,
  volumeBounds,
  volumeJitter,
  volumeRay,
} from '../../../shader-gen/space/volume-3d.ts';
import { walk3d } from '../../../shader-gen/space/walk.ts';
import { linearToSrgb, toLinear } from '../../../shader-gen/srgb.ts';
import { NESTED, NO_MIRRORS, ONE_MIRROR, VOLUME } from './volume-scenes.ts';

const SEED = { seed: 1010, numRuns: 200 };

describe('volume renderer (CPU)', () => {
  it('draws only the background without mirrors', () => {
    const r = renderScene3d(NO_MIRRORS, 16, 12, { samples: 1 });
    const bg = NO_MIRRORS.background.map((c) => Math.round(255 * c));
    for (let i = 0; i < r.data.length; i += 4) expect([...r.data.slice(i, i + 4)]).toEqual([...bg, 255]);
    expect(volumeBounds(prepareTrace3d(NO_MIRRORS))).toBeNull();
  });

  it("gives one mirror's optical depth as density × chord (within one sample)", () => {
    const plan = prepareTrace3d(ONE_MIRROR);
    const vb = volumeBounds(plan)!;
    const basis = cameraBasis(ONE_MIRROR.camera);
    const o = basis.origin;
    let inside = 0;
    for (let py = 0; py < 24; py++) {
      for (let px = 0; px < 32; px++) {
        const d = rayDirection(basis, 32, 24, px + 0.5, py + 0.5);
        const r = volumeRay(plan, vb, VOLUME, o, d, volumeJitter(px, py));
        // Chord of the unit ball: 2·√(1 − b²), b the distance from the centre to the ray's line.
        const along = -(o[0] * d[0] + o[1] * d[1] + o[2] * d[2]);
        const b2 = o[0] ** 2 + o[1] ** 2 + o[2] ** 2 - along * along;
        const chord = b2 < 1 ? 2 * Math.sqrt(1 - b2) : 0;
        if (chord > 0) inside++;
        // The samples are Δt apart: the count inside the chord is chord/Δt ± 1.
        const span = 2 * vb.bounds.radius;
        const dt = Math.min(span, 2 * Math.sqrt(Math.max(0, vb.bounds.radius ** 2 - b2))) / VOLUME.steps;
        expect(Math.abs(r.opticalDepth - VOLUME.density * chord)).toBeLessThanOrEqual(
          VOLUME.density * dt + 1e-9,
        );
        expect(r.transmittance).toBeCloseTo(Math.exp(-r.opticalDepth), 12);
      }
    }
    expect(inside).toBeGreaterThan(100); // the mirror covers part of the view
  });

  it('a point nested in one more mirror image has depth one more and no less extinction', () => {
    // Fig. 11's mirrors are disjoint: I_i(q) for q in mirror j ≠ i lies in mirror i only, and the
    // walk's first step takes it back to q.
    const plan = prepareTrace3d(NESTED);
    const mirrors = NESTED.elements.map((e) => (e as { sphere: Sphere }).sphere);
    const depth = (p: Vec3) => walk3d(plan, p[0], p[1], p[2], false).depth;
    const inBall = (s: Sphere) =>
      fc
        .tuple(fc.double({ min: -1, max: 1 }), fc.double({ min: -1, max: 1 }), fc.double({ min: -1, max: 1 }))
        .filter(([x, y, z]) => x * x + y * y + z * z < 0.98 && x * x + y * y + z * z > 0.01)
        .map(
          ([x, y, z]): Vec3 => [
            s.center[0] + s.radius * x,
            s.center[1] + s.radius * y,
            s.center[2] + s.radius * z,
          ],
        );
    fc.assert(
      fc.property(
        fc.integer({ min: 0, max: 5 }),
        fc.integer({ min: 1, max: 5 }),
        fc.integer({ min: 0, max: 3 }),
        inBall(mirrors[0]!),
        (i, shift, nest, unit) => {
          // q: a point of mirror j, pushed `nest` levels deeper through other mirrors first.
          const to = mirrors[(i + shift) % 6]!.center;
          const from = mirrors[0]!.center;
          let q: Vec3 = [unit[0] - from[0] + to[0], unit[1] - from[1] + to[1], unit[2] - from[2] + to[2]];
          let last = (i + shift) % 6;
          for (let n = 0; n < nest; n++) {
            const m = (last + 1 + n) % 6;
            q = invertInSphere(mirrors[m]!, q)!.x;
            last = m;
          }
          fc.pre(last !== i);
          const k = depth(q);
          // Points that need the whole budget (near a limit point) have no deeper depth to find.
          fc.pre(k < NESTED.maxIterations - 1);
          const p = invertInSphere(mirrors[i]!, q)!.x;
          expect(depth(p)).toBe(k + 1);
          expect(extinction(VOLUME, k + 1)).toBeGreaterThanOrEqual(extinction(VOLUME, k));
        },
      ),
      SEED,
    );
  });

  it('keeps T = e^(−τ) and stops once the ray is opaque', () => {
    const plan = prepareTrace3d(ONE_MIRROR);
    const vb = volumeBounds(plan)!;
    const dense = { ...VOLUME, density: 40 };
    const r = volumeRay(plan, vb, dense, [0, -5, 0], [0, 1, 0], 0.5);
    expect(r.transmittance).toBeLessThan(EXIT_TRANSMITTANCE);
    expect(r.samples).toBeLessThan(dense.steps / 2);
    expect(r.opticalDepth).toBeLessThan(-Math.log(EXIT_TRANSMITTANCE) + 40 * (2 / dense.steps));
    // Through the centre, thin: the whole chord of 2 is sampled.
    const thin = volumeRay(plan, vb, VOLUME, [0, -5, 0], [0, 1, 0], 0.5);
    expect(thin.samples).toBe(VOLUME.steps);
    expect(thin.opticalDepth).toBeCloseTo(VOLUME.density * 2, 1);
  });

  it('draws the nesting: rays through the clusters are more opaque than rays through one shell', () => {
    const r = renderScene3d(NESTED, 48, 36, { samples: 1 });
    const bg = toLinear(NESTED.background);
    const lum = (i: number) =>
      [0, 1, 2].reduce((s, k) => s + Math.abs(r.data[i + k]! - Math.round(255 * linearToSrgb(bg[k]!))), 0);
    const values = Array.from({ length: 48 * 36 }, (_, p) => lum(4 * p));
    const lit = values.filter((v) => v > 8).length;
    expect(lit).toBeGreaterThan(0.2 * values.length); // not empty
    expect(lit).toBeLessThan(0.95 * values.length); // not a wall
    // The centre of the picture (the nested clusters) differs more from the background than the rim of a shell.
    expect(Math.max(...values)).toBeGreaterThan(4 * Math.min(...values.filter((v) => v > 8)));
  });

  it('offsets each pixel deterministically, spread over [0, 1)', () => {
    const js = Array.from({ length: 64 * 64 }, (_, p) => volumeJitter(p % 64, Math.floor(p / 64)));
    expect(js.every((j) => j >= 0 && j < 1)).toBe(true);
    expect(volumeJitter(17, 5)).toBe(volumeJitter(17, 5));
    expect(new Set(js).size).toBeGreaterThan(4000);
    const mean = js.reduce((s, j) => s + j, 0) / js.length;
    expect(Math.abs(mean - 0.5)).toBeLessThan(0.02);
    // Neighbours are not correlated (no banding): mean |j(x+1) − j(x)| ≈ 1/3 for independent offsets.
    const step = js.slice(1).reduce((s, j, p) => s + Math.abs(j - js[p]!), 0) / (js.length - 1);
    expect(step).toBeGreaterThan(0.28);
  });
});
