/**
 * "Explain this pixel" in volume mode (shader-gen/space/explain-volume-3d.ts): the explanation of a
 * pixel is the render's own ray — the same opacity, optical depth and sample count as the volume
 * probe, the same colour as a one-sample render — its depth runs cover every sample taken, each
 * run's depth is the walk's depth at its first sample, a dense volume is reported as exiting early,
 * and a ray that misses the mirrors' ball takes no samples and shows the background.
 */
import { describe, expect, it } from 'vitest';
import { cameraBasis, rayDirection } from '../../../shader-gen/space/camera-3d.ts';
import { explainVolumePixel3d } from '../../../shader-gen/space/explain-volume-3d.ts';
import { prepareTrace3d } from '../../../shader-gen/space/plan.ts';
import { probeVolume3d, renderScene3d } from '../../../shader-gen/space/render-3d.ts';
import { EXIT_TRANSMITTANCE } from '../../../shader-gen/space/volume-3d.ts';
import { walkDepth3d } from '../../../shader-gen/space/walk.ts';
import { NESTED, ONE_MIRROR, VOLUME } from './volume-scenes.ts';

const W = 16;
const H = 12;

describe('explainVolumePixel3d', () => {
  it('is the render’s own ray: the probe’s opacity, optical depth and samples, the render’s colour', () => {
    const probe = probeVolume3d(NESTED, W, H);
    const picture = renderScene3d(NESTED, W, H, { samples: 1 });
    let deep = 0;
    for (let py = 0; py < H; py++)
      for (let px = 0; px < W; px++) {
        const e = explainVolumePixel3d(NESTED, W, H, px + 0.5, py + 0.5);
        const at = 4 * (py * W + px);
        expect(e.opacity).toBeCloseTo(probe[at]!, 5);
        expect(e.opticalDepth).toBeCloseTo(probe[at + 1]!, 4);
        expect(e.samples).toBe(probe[at + 2]);
        // The picture's row 0 is the top; its bytes are 8-bit sRGB.
        const o = 4 * ((H - 1 - py) * W + px);
        const bytes = [...e.colour.map((c) => Math.round(255 * c)), Math.round(255 * e.alpha)];
        expect(bytes).toEqual([...picture.data.slice(o, o + 4)]);
        if (e.deepest >= 2) deep++;
      }
    expect(deep).toBeGreaterThan(4); // the nested clusters are seen, not just the mirrors
  });

  it('lists the depths as runs over every sample taken, each run the walk’s depth at its start', () => {
    const plan = prepareTrace3d(NESTED);
    const basis = cameraBasis(NESTED.camera);
    for (const [px, py] of [
      [W / 2, H / 2],
      [W / 3, H / 2],
      [W / 2, H / 4],
    ] as const) {
      const e = explainVolumePixel3d(NESTED, W, H, px, py);
      expect(e.direction).toEqual(rayDirection(basis, W, H, px, py));
      expect(e.span).not.toBeNull();
      expect(e.runs.reduce((n, r) => n + r.samples, 0)).toBe(e.samples);
      for (let i = 1; i < e.runs.length; i++) expect(e.runs[i]!.depth).not.toBe(e.runs[i - 1]!.depth);
      for (const r of e.runs) {
        const p = e.direction.map((d, k) => e.origin[k]! + d * r.from);
        expect(walkDepth3d(plan, p[0]!, p[1]!, p[2]!)).toBe(r.depth);
      }
      // Sample i lies at t₀ + (i + j)·Δt: the first run starts at the first sample.
      expect(e.runs[0]!.from).toBeCloseTo(e.span![0] + e.jitter * e.dt, 9);
      expect(e.deepest).toBe(Math.max(...e.runs.map((r) => r.depth)));
    }
  });

  it('through one mirror (the volume’s bounds are that ball) every sample has depth 1 and is taken', () => {
    const e = explainVolumePixel3d(ONE_MIRROR, W, H, W / 2, H / 2);
    expect(e.runs.map((r) => r.depth)).toEqual([1]);
    expect(e.samples).toBe(VOLUME.steps);
    expect(e.exitedEarly).toBe(false);
    expect(e.opticalDepth).toBeCloseTo(VOLUME.density * 2, 1); // density × the chord 2
  });

  it('says when a dense volume turned the ray opaque before its last sample', () => {
    const dense = { ...ONE_MIRROR, volume: { ...VOLUME, density: 40 } };
    const e = explainVolumePixel3d(dense, W, H, W / 2, H / 2);
    expect(e.exitedEarly).toBe(true);
    expect(e.samples).toBeLessThan(VOLUME.steps);
    expect(e.opacity).toBeGreaterThan(1 - EXIT_TRANSMITTANCE);
    expect(e.runs.at(-1)!.depth).toBe(1); // it stopped inside the mirror
  });

  it('a ray past the mirrors’ ball takes no samples and shows the background', () => {
    const e = explainVolumePixel3d(ONE_MIRROR, W, H, 0.5, 0.5);
    expect(e.span).toBeNull();
    expect(e.samples).toBe(0);
    expect(e.runs).toEqual([]);
    expect(e.opacity).toBe(0);
    expect(e.colour.map((c) => Math.round(255 * c))).toEqual(
      ONE_MIRROR.background.map((c) => Math.round(255 * c)),
    );
  });
});
