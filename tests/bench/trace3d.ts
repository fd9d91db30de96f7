/**
 * 3D sphere tracer speed (part of `npm run bench`; alone: `npx tsx tests/bench/trace3d.ts [rounds]`):
 * ms per frame at 512² on SwiftShader for the Fig. 11 scene (tests/shader-gen/space/scenes-3d.ts)
 * — the generated uniform program (U), the generated baked one (B) and the hand-written tracer of
 * the same scene (H, tests/bench/hand-written/fig11-trace.frag), all probe output, INTERLEAVED
 * (U B H U B H …), each frame ended by readPixels; plus one colour frame of each generated program
 * (normals, occlusion and shadow on top). Ratios are medians of per-round ratios. Prints figures,
 * never fails on a time (the goal for baked/hand is ≤ 1.10).
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { GpuProbe } from '../parity/gpu-probe.ts';
import { FIG11 } from '../shader-gen/space/scenes-3d.ts';
import { FRAME_SIZE, median, medianRatio, printTable } from './report.ts';

export const ROUNDS = 5;
const HAND = readFileSync(new URL('./hand-written/fig11-trace.frag', import.meta.url), 'utf8');
const ms = (x: number) => x.toFixed(0);
const times = (x: number) => `${x.toFixed(2)}×`;

export async function run(rounds = ROUNDS): Promise<void> {
  const gpu = await GpuProbe.open(FRAME_SIZE, FRAME_SIZE);
  try {
    const camera = cameraUniforms(FIG11.camera);
    const build = async (source: string, vertex: string, uniforms: typeof camera) => ({
      index: await gpu.program(vertex, source),
      uniforms: [...uniforms, ...camera],
    });
    const u = compile3d(FIG11, { variant: 'probe' });
    const b = compile3d(FIG11, { variant: 'probe', bake: true });
    const programs = {
      uniform: await build(u.source, u.vertexSource, u.uniforms),
      baked: await build(b.source, b.vertexSource, b.uniforms),
      hand: await build(HAND, u.vertexSource, []),
    };
    const times_: Record<keyof typeof programs, number[]> = { uniform: [], baked: [], hand: [] };
    const frame = async (p: { index: number; uniforms: typeof camera }) =>
      (await gpu.render(p.index, p.uniforms, { center: [0, 0], scale: 1 })).ms;
    // One warm-up frame each (SwiftShader finishes its JIT on the first draw).
    for (const p of Object.values(programs)) await frame(p);
    for (let r = 0; r < rounds; r++) {
      for (const [name, p] of Object.entries(programs))
        times_[name as keyof typeof programs].push(await frame(p));
    }
    const colour = async (bake: boolean) => {
      const c = compile3d(FIG11, { bake });
      const p = await build(c.source, c.vertexSource, c.uniforms);
      await frame(p);
      return frame(p);
    };
    console.log(
      `\n3D sphere tracer, Fig. 11 scene, ${FRAME_SIZE}², Chromium WebGL2 (${gpu.renderer}), ` +
        `${rounds} interleaved rounds (U B H …), probe output; colour = one shaded frame.\n`,
    );
    printTable(
      [
        'uniform ms',
        'baked ms',
        'hand ms',
        'baked/hand',
        'uniform/hand',
        'colour uniform ms',
        'colour baked ms',
      ],
      [
        [
          ms(median(times_.uniform)),
          ms(median(times_.baked)),
          ms(median(times_.hand)),
          times(medianRatio(times_.baked, times_.hand)),
          times(medianRatio(times_.uniform, times_.hand)),
          ms(await colour(false)),
          ms(await colour(true)),
        ],
      ],
    );
  } finally {
    await gpu.close();
  }
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const rounds = Number(process.argv[2] ?? ROUNDS);
  run(Number.isInteger(rounds) && rounds >= 1 ? rounds : ROUNDS).catch((e) => {
    console.error(e);
    process.exitCode = 1;
  });
}
