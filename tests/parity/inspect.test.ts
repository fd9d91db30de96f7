/**
 * The inspect variant ("Explain this pixel": the depth the editor reads back from the GPU) agrees
 * with the CPU trace of what the picture does there (shader-gen/trace.ts tracePicture) on examples
 * with a clip disk and with orbit seeds: same stop reason and depth at ≥ 99 % of the pixel centres
 * (the rest lie on a mirror or a seed's rim, where float32 and float64 may decide differently).
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { pixelToWorld } from '../../nodes/core/view.ts';
import { compile, INSPECT_STOP } from '../../shader-gen/compile.ts';
import { type IisTrace, tracePicture } from '../../shader-gen/trace.ts';
import { loadExample } from '../support/examples.ts';
import { GpuProbe } from './gpu-probe.ts';

const SIZE = 48;
let gpu: GpuProbe;

beforeAll(async () => {
  gpu = await GpuProbe.open(SIZE, SIZE);
});
afterAll(async () => {
  await gpu?.close();
});

/** The inspect variant's w for a CPU trace (INSPECT_STOP). */
function stopCode(t: IisTrace): number {
  if (t.stop === 'clipped') return INSPECT_STOP.clipped;
  if (t.stop === 'seed') return INSPECT_STOP.seed + t.seed;
  return t.stop === 'limit' ? INSPECT_STOP.limit : INSPECT_STOP.tile;
}

describe('inspect variant = CPU trace of the picture', () => {
  it.each([
    ['hyperbolic-237', 'clipped'],
    ['glide-reflection-frieze', 'seed'],
    ['spiral-similarity-pearls', 'seed'],
  ])('%s (shows %s points)', async (name, expected) => {
    const { scene } = loadExample(name);
    const program = compile(scene, { variant: 'inspect' });
    const index = await gpu.program(program.vertexSource, program.source);
    const img = await gpu.render(index, program.uniforms, scene.view, { pictures: program.pictures });
    let agree = 0;
    const seen = new Set<string>();
    for (let py = 0; py < SIZE; py++) {
      for (let px = 0; px < SIZE; px++) {
        const t = tracePicture(scene, pixelToWorld(scene.view, SIZE, SIZE, px, py));
        seen.add(t.stop);
        const o = 4 * (py * SIZE + px);
        if (img.data[o] === t.depth && img.data[o + 3] === stopCode(t)) agree++;
      }
    }
    expect(seen).toContain(expected);
    expect(seen).toContain('fundamental-domain');
    expect(agree / (SIZE * SIZE)).toBeGreaterThanOrEqual(0.99);
  });
});
