/**
 * GPU = CPU for the mirror material (docs/math-3d.md "Mirror material") in real Chromium (WebGL2
 * through SwiftShader), in the style of the shading row of trace3d-parity.test.ts: the colour
 * program's linear RGB per pixel centre against the CPU reference (render-3d.ts tracePixel, then
 * reflect-3d.ts radiance) — mirrors reflecting once under the flat background, and the Fig. 37
 * example (three bounces under the sky) (small images: SwiftShader runs the bounce loop per pixel). Background pixels are compared too: they are the environment.
 */
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { environmentOf, radiance } from '../../shader-gen/space/reflect-3d.ts';
import { exampleScenes3d, MIRROR_FIG11 } from '../shader-gen/space/scenes-3d.ts';
import { colourDiffs3d } from './colour-3d.ts';
import type { GpuProbe } from './gpu-probe.ts';
import { probeForSuite } from './probe-suite.ts';

const W = 24;
const H = 18;

/**
 * Opt-in (KLEINFLOW_MIRROR_PARITY=1): on the shared 2-core test machine SwiftShader did not finish
 * even a 4×3 draw of the mirror program in about four minutes; the same scene with its mirrors made
 * matte (flat background too) was as slow, while Fig. 11 drew 4×3 in 0.5 s, so the cause is in
 * this scene (four outer seeds), not in the reflection loop — not found yet. In the default run
 * this file would only time out. Not yet seen passing: see docs/math-3d.md
 * "Mirror material".
 */
const OPT_IN = process.env.KLEINFLOW_MIRROR_PARITY !== '1';

let gpu: GpuProbe;
const rows = probeForSuite(
  W,
  H,
  'Mirror material: GPU vs CPU colour',
  (g) => {
    gpu = g;
  },
  { skip: OPT_IN },
);

describe.skipIf(OPT_IN)('mirror material: GPU = CPU (SwiftShader)', () => {
  const scenes: Record<string, Scene3d> = {
    'reflections 1, flat': { ...MIRROR_FIG11, reflections: 1, environment: { mode: 'flat' } },
    'fig37 example': exampleScenes3d()['fig37-indras-bubbles-mirror']!,
  };
  for (const [name, scene] of Object.entries(scenes)) {
    it(`${name}: the colour agrees pixel by pixel`, async () => {
      const env = environmentOf(scene);
      let mirrored = 0;
      const { median, p95 } = await colourDiffs3d(gpu, scene, 1, (plan, r) => {
        if (r.hit.hit && scene.seeds[r.hit.seed]!.reflectivity) mirrored++;
        return radiance(plan, env, r.o, r.d, r.angle, r.hit);
      });
      rows[name] = { 'mirror pixels': mirrored, median: median.toFixed(5), p95: p95.toFixed(5) };
      expect(mirrored).toBeGreaterThan(0.03 * W * H);
      expect(median).toBeLessThan(0.002);
      expect(p95).toBeLessThan(0.03);
    }, 300_000);
  }
});
