/**
 * GPU = CPU for the volume renderer (docs/math-3d.md "§11 Volume rendering of the nesting depth") in
 * real Chromium (WebGL2 through SwiftShader): compile3d's volume probe, (opacity, optical depth,
 * samples, 0) per pixel centre, agrees with the float64 CPU reference (render-3d.ts probeVolume3d),
 * the same hashed sample offsets included; the colour program's medium over the background matches
 * volume-3d.ts; the hand-written bench renderer draws the same picture; new values re-render
 * without a new program.
 */
import { describe, expect, it } from 'vitest';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { rayDirection } from '../../shader-gen/space/camera-3d.ts';
import { cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { probeVolume3d, render3dFrame } from '../../shader-gen/space/render-3d.ts';
import { overBackground, volumeJitter, volumeRay } from '../../shader-gen/space/volume-3d.ts';
import { HAND_WRITTEN_VOLUME } from '../bench/hand-written/trace3d.ts';
import { opacityDiffer } from '../bench/volume3d.ts';
import { exampleScenes3d } from '../shader-gen/space/scenes-3d.ts';
import { NESTED, ONE_MIRROR } from '../shader-gen/space/volume-scenes.ts';
import { render3d } from './colour-3d.ts';
import type { GpuProbe } from './gpu-probe.ts';
import { probeForSuite } from './probe-suite.ts';

const W = 64;
const H = 48;
/**
 * A sample whose point lies within a float32 rounding of a sphere of the orbit counts a different
 * depth on the GPU; it moves the opacity by at most that sample's α, so almost every pixel agrees
 * closely and a few differ by one sample.
 */
const OPACITY_TOLERANCE = 0.02;
const MIN_AGREEMENT = 0.99;

let gpu: GpuProbe;
const rows = probeForSuite(W, H, 'Volume GPU vs CPU parity', (g) => {
  gpu = g;
});

const gpuImage = (scene: Scene3d, variant: 'color' | 'volume-probe') => render3d(gpu, scene, { variant });

describe('volume renderer: GPU = CPU (SwiftShader)', () => {
  const scenes: Record<string, Scene3d> = { 'one mirror': ONE_MIRROR, nested: NESTED };
  for (const [name, scene] of Object.entries(scenes)) {
    it(`${name}: opacity within ${OPACITY_TOLERANCE} on ≥ 99 % of pixels, optical depth alike`, async () => {
      const image = await gpuImage(scene, 'volume-probe');
      const cpu = probeVolume3d(scene, W, H);
      let agree = 0;
      let seen = 0;
      const tauErrors: number[] = [];
      for (let i = 0; i < W * H * 4; i += 4) {
        if (cpu[i]! > 0.05) seen++;
        if (Math.abs(image.data[i]! - cpu[i]!) <= OPACITY_TOLERANCE) agree++;
        if (cpu[i]! < 0.95) tauErrors.push(Math.abs(image.data[i + 1]! - cpu[i + 1]!));
      }
      tauErrors.sort((a, b) => a - b);
      const median = tauErrors[Math.floor(tauErrors.length / 2)]!;
      rows[name] = {
        agreement: `${((100 * agree) / (W * H)).toFixed(2)} %`,
        seen,
        'τ median error': median.toFixed(5),
        'GPU ms': Math.round(image.ms),
      };
      expect(seen).toBeGreaterThan(0.1 * W * H); // the picture is not empty
      expect(agree / (W * H)).toBeGreaterThanOrEqual(MIN_AGREEMENT);
      expect(median).toBeLessThan(1e-3);
    }, 300_000);
  }

  it('the colour program composites like the CPU (medium over the background)', async () => {
    const image = await gpuImage(NESTED, 'color');
    const f = render3dFrame(NESTED, W, H);
    const diffs: number[] = [];
    for (let py = 0; py < H; py++) {
      for (let px = 0; px < W; px++) {
        const d = rayDirection(f.basis, W, H, px + 0.5, py + 0.5);
        const r = volumeRay(f.plan, f.volumeBounds, NESTED.volume!, f.basis.origin, d, volumeJitter(px, py));
        const [c, a] = overBackground(r, f.bg, 1);
        const o = 4 * (py * W + px);
        expect(image.data[o + 3]).toBeCloseTo(a, 5);
        diffs.push(Math.max(...[0, 1, 2].map((k) => Math.abs(c[k]! - image.data[o + k]!))));
      }
    }
    diffs.sort((a, b) => a - b);
    const median = diffs[Math.floor(diffs.length / 2)]!;
    const p99 = diffs[Math.floor(diffs.length * 0.99)]!;
    rows['nested colour'] = { median: median.toFixed(5), p99: p99.toFixed(5) };
    expect(median).toBeLessThan(0.002);
    expect(p99).toBeLessThan(0.03);
  }, 300_000);

  for (const { example, source } of HAND_WRITTEN_VOLUME) {
    it(`the hand-written bench renderer draws what the generated program draws (${example})`, async () => {
      const scene = exampleScenes3d()[example]!;
      const generated = await gpuImage(scene, 'volume-probe');
      const index = await gpu.program(compile3d(scene).vertexSource, source);
      const image = await gpu.render(index, cameraUniforms(scene.camera), { center: [0, 0], scale: 1 });
      expect(image.data.filter((v, i) => i % 4 === 0 && v > 0.05).length).toBeGreaterThan(0.1 * W * H);
      expect(opacityDiffer(generated.data, image.data)).toBeLessThan(0.01);
    }, 300_000);
  }

  it('new volume values re-render from uniforms without a new program', async () => {
    const denser: Scene3d = { ...NESTED, volume: { ...NESTED.volume!, density: 4 } };
    const a = compile3d(NESTED, { variant: 'volume-probe' });
    const b = compile3d(denser, { variant: 'volume-probe' });
    expect(b.source).toBe(a.source);
    const index = await gpu.program(a.vertexSource, a.source);
    const before = await gpu.compileCount();
    const thin = await gpu.render(index, [...a.uniforms, ...cameraUniforms(NESTED.camera)], {
      center: [0, 0],
      scale: 1,
    });
    const thick = await gpu.render(index, [...b.uniforms, ...cameraUniforms(NESTED.camera)], {
      center: [0, 0],
      scale: 1,
    });
    expect(await gpu.compileCount()).toBe(before);
    const opacity = (data: Float32Array) => data.reduce((s, v, i) => (i % 4 === 0 ? s + v : s), 0);
    expect(opacity(thick.data)).toBeGreaterThan(1.5 * opacity(thin.data));
  }, 300_000);
});
