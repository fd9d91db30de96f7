/**
 * GPU = CPU for the mirror material (docs/math-3d.md "Mirror material") in real Chromium (WebGL2
 * through SwiftShader), in the style of the shading row of trace3d-parity.test.ts: the colour
 * program's linear RGB per pixel centre against the CPU reference (render-3d.ts tracePixel, then
 * reflect-3d.ts radiance) — mirrors reflecting once under the flat background, and the Fig. 37
 * example (three bounces under the sky). Background pixels are compared too: they are the
 * environment; and the mirror pixels apart, since in Fig. 37 they are a few per cent of the image
 * and the sky around them would carry the percentiles of the whole image alone.
 */
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { environmentOf, radiance } from '../../shader-gen/space/reflect-3d.ts';
import { exampleScenes3d, MIRROR_FIG11 } from '../shader-gen/space/scenes-3d.ts';
import { colourDiffs3d, type TracedPixel } from './colour-3d.ts';
import type { GpuProbe } from './gpu-probe.ts';
import { probeForSuite } from './probe-suite.ts';

const W = 64;
const H = 48;

let gpu: GpuProbe;
const rows = probeForSuite(W, H, 'Mirror material: GPU vs CPU colour', (g) => {
  gpu = g;
});

describe('mirror material: GPU = CPU (SwiftShader)', () => {
  const scenes: Record<string, Scene3d> = {
    'reflections 1, flat': { ...MIRROR_FIG11, reflections: 1, environment: { mode: 'flat' } },
    'fig37 example': exampleScenes3d()['fig37-indras-bubbles-mirror']!,
  };
  for (const [name, scene] of Object.entries(scenes)) {
    it(`${name}: the colour agrees pixel by pixel`, async () => {
      const env = environmentOf(scene);
      const mirror = (r: TracedPixel) => r.hit.hit && Boolean(scene.seeds[r.hit.seed]!.reflectivity);
      const all = await colourDiffs3d(gpu, scene, 1, (plan, r) =>
        radiance(plan, env, r.o, r.d, r.angle, r.hit),
      );
      const mirrors = await colourDiffs3d(gpu, scene, 1, (plan, r) =>
        mirror(r) ? radiance(plan, env, r.o, r.d, r.angle, r.hit) : null,
      );
      rows[name] = {
        'mirror pixels': mirrors.pixels,
        median: all.median.toFixed(5),
        p95: all.p95.toFixed(5),
        'mirror median': mirrors.median.toFixed(5),
        'mirror p95': mirrors.p95.toFixed(5),
      };
      expect(mirrors.pixels).toBeGreaterThan(0.03 * W * H);
      for (const p of [all, mirrors]) {
        expect(p.median).toBeLessThan(0.002);
        expect(p.p95).toBeLessThan(0.03);
      }
    }, 300_000);
  }
});
