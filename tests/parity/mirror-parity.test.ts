/**
 * GPU = CPU for the mirror material (docs/math-3d.md "Mirror material") in real Chromium (WebGL2
 * through SwiftShader), in the style of the shading row of trace3d-parity.test.ts: the colour
 * program's linear RGB per pixel centre against the CPU reference (render-3d.ts tracePixel, then
 * reflect-3d.ts radiance) — mirrors reflecting once under the flat background, and the Fig. 37
 * example (three bounces under the sky) (small images: SwiftShader runs the
 * bounce loop per pixel). Background pixels are compared too: they are the environment.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { prepareTrace3d } from '../../shader-gen/space/plan.ts';
import { environmentOf, radiance } from '../../shader-gen/space/reflect-3d.ts';
import { tracePixel } from '../../shader-gen/space/render-3d.ts';
import { exampleScenes3d, MIRROR_FIG11 } from '../shader-gen/space/scenes-3d.ts';
import { GpuProbe } from './gpu-probe.ts';

const W = 64;
const H = 48;

let gpu: GpuProbe;
const rows: Record<string, Record<string, string | number>> = {};

beforeAll(async () => {
  gpu = await GpuProbe.open(W, H);
});

afterAll(async () => {
  console.log(`\nMirror material: GPU vs CPU colour (${W}×${H}, SwiftShader):`);
  console.table(rows);
  await gpu?.close();
});

/** Median and 95th percentile of absolute differences. */
function percentiles(values: number[]): { median: number; p95: number } {
  const sorted = [...values].sort((a, b) => a - b);
  return { median: sorted[Math.floor(sorted.length / 2)]!, p95: sorted[Math.floor(sorted.length * 0.95)]! };
}

describe('mirror material: GPU = CPU (SwiftShader)', () => {
  const scenes: Record<string, Scene3d> = {
    'reflections 1, flat': { ...MIRROR_FIG11, reflections: 1, environment: { mode: 'flat' } },
    'fig37 example': exampleScenes3d()['fig37-indras-bubbles-mirror']!,
  };
  for (const [name, scene] of Object.entries(scenes)) {
    it(`${name}: the colour agrees pixel by pixel`, async () => {
      const c = compile3d(scene);
      const index = await gpu.program(c.vertexSource, c.source);
      const image = await gpu.render(index, [...c.uniforms, ...cameraUniforms(scene.camera)], {
        center: [0, 0],
        scale: 1,
      });
      const plan = prepareTrace3d(scene);
      const env = environmentOf(scene);
      const diffs: number[] = [];
      // The mirror pixels apart too: in Fig. 37 they are a few per cent of the image, and the sky
      // around them would carry the percentiles of the whole image alone.
      const mirrorDiffs: number[] = [];
      for (let py = 0; py < H; py++) {
        for (let px = 0; px < W; px++) {
          const r = tracePixel(plan, W, H, px + 0.5, py + 0.5);
          const cpu = radiance(plan, env, r.o, r.d, r.angle, r.hit);
          const o = 4 * (py * W + px);
          const diff = Math.max(...[0, 1, 2].map((k) => Math.abs(cpu[k]! - image.data[o + k]!)));
          diffs.push(diff);
          if (r.hit.hit && scene.seeds[r.hit.seed]!.reflectivity) mirrorDiffs.push(diff);
        }
      }
      const all = percentiles(diffs);
      const mirror = percentiles(mirrorDiffs);
      rows[name] = {
        'mirror pixels': mirrorDiffs.length,
        median: all.median.toFixed(5),
        p95: all.p95.toFixed(5),
        'mirror median': mirror.median.toFixed(5),
        'mirror p95': mirror.p95.toFixed(5),
      };
      expect(mirrorDiffs.length).toBeGreaterThan(0.03 * W * H);
      for (const p of [all, mirror]) {
        expect(p.median).toBeLessThan(0.002);
        expect(p.p95).toBeLessThan(0.03);
      }
    }, 300_000);
  }
});
