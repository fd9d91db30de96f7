/**
 * Volume renderer speed (part of `npm run bench`; alone: `npx tsx tests/bench/volume3d.ts [rounds]`):
 * for each example with a hand-written volume renderer (tests/bench/hand-written/trace3d.ts
 * HAND_WRITTEN_VOLUME — written for speed for that one picture, not a copy of the generated
 * program), ms per frame at 512² on SwiftShader of the generated uniform volume probe (U), the baked
 * one (B) and the hand-written one (H), interleaved (U B H U B H …), each frame ended by readPixels;
 * ratios are medians of per-round ratios; "opacity differ" is the fraction of pixels whose opacity
 * differs by more than 0.02 between B and H. Plus one colour frame of the generated baked program.
 * Prints figures, never fails on a time.
 */
import { fileURLToPath } from 'node:url';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { cameraUniforms, compile3d } from '../../shader-gen/space/compile-3d.ts';
import { GpuProbe } from '../parity/gpu-probe.ts';
import { exampleScenes3d } from '../shader-gen/space/scenes-3d.ts';
import { HAND_WRITTEN_VOLUME } from './hand-written/trace3d.ts';
import { FRAME_SIZE, median, medianRatio, printTable } from './report.ts';

export const ROUNDS = 5;
const ms = (x: number) => x.toFixed(0);
const times = (x: number) => `${x.toFixed(2)}×`;

/** Fraction of pixels whose channel-0 opacity differs by more than `tolerance`. */
export function opacityDiffer(a: Float32Array, b: Float32Array, tolerance = 0.02): number {
  let differ = 0;
  for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i]! - b[i]!) > tolerance) differ++;
  return differ / (a.length / 4);
}

async function benchScene(gpu: GpuProbe, name: string, scene: Scene3d, hand: string, rounds: number) {
  const camera = cameraUniforms(scene.camera);
  const u = compile3d(scene, { variant: 'volume-probe' });
  const b = compile3d(scene, { variant: 'volume-probe', bake: true });
  const programs = {
    uniform: { index: await gpu.program(u.vertexSource, u.source), uniforms: [...u.uniforms, ...camera] },
    baked: { index: await gpu.program(b.vertexSource, b.source), uniforms: [...b.uniforms, ...camera] },
    hand: { index: await gpu.program(u.vertexSource, hand), uniforms: camera },
  };
  const frame = (p: (typeof programs)['hand']) =>
    gpu.render(p.index, p.uniforms, { center: [0, 0], scale: 1 });
  await frame(programs.uniform);
  const bakedImage = await frame(programs.baked);
  const handImage = await frame(programs.hand);
  const t: Record<keyof typeof programs, number[]> = { uniform: [], baked: [], hand: [] };
  for (let r = 0; r < rounds; r++)
    for (const key of ['uniform', 'baked', 'hand'] as const) t[key].push((await frame(programs[key])).ms);
  const c = compile3d(scene, { bake: true });
  const colour = { index: await gpu.program(c.vertexSource, c.source), uniforms: [...c.uniforms, ...camera] };
  await frame(colour);
  const colourMs = (await frame(colour)).ms;
  return [
    name,
    ms(median(t.uniform)),
    ms(median(t.baked)),
    ms(median(t.hand)),
    times(medianRatio(t.baked, t.hand)),
    times(medianRatio(t.uniform, t.hand)),
    `${(100 * opacityDiffer(bakedImage.data, handImage.data)).toFixed(2)} %`,
    ms(colourMs),
  ];
}

export async function run(rounds = ROUNDS): Promise<void> {
  const gpu = await GpuProbe.open(FRAME_SIZE, FRAME_SIZE);
  try {
    const scenes = exampleScenes3d();
    const rows: string[][] = [];
    for (const { example, source } of HAND_WRITTEN_VOLUME)
      rows.push(await benchScene(gpu, example, scenes[example]!, source, rounds));
    console.log(
      `\nVolume renderer (Fig. 10) against a hand-written one written for speed, ${FRAME_SIZE}², Chromium ` +
        `WebGL2 (${gpu.renderer}), ${rounds} interleaved rounds (U B H …), volume probe output; colour = ` +
        'one baked colour frame.\n',
    );
    printTable(
      [
        'example',
        'uniform ms',
        'baked ms',
        'hand ms',
        'baked/hand',
        'uniform/hand',
        'opacity differ',
        'colour ms',
      ],
      rows,
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
