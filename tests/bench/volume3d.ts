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
import { GpuProbe } from '../parity/gpu-probe.ts';
import { exampleScenes3d } from '../shader-gen/space/scenes-3d.ts';
import { HAND_WRITTEN_VOLUME } from './hand-written/trace3d.ts';
import { FRAME_SIZE, printTable } from './report.ts';
import { benchScene } from './trace3d.ts';

export const ROUNDS = 5;
const _ms = (x: number) => x.toFixed(0);
const _times = (x: number) => `${x.toFixed(2)}×`;

/** Fraction of pixels whose channel-0 opacity differs by more than `tolerance`. */
export function opacityDiffer(a: Float32Array, b: Float32Array, tolerance = 0.02): number {
  let differ = 0;
  for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i]! - b[i]!) > tolerance) differ++;
  return differ / (a.length / 4);
}

export async function run(rounds = ROUNDS): Promise<void> {
  const gpu = await GpuProbe.open(FRAME_SIZE, FRAME_SIZE);
  try {
    const scenes = exampleScenes3d();
    const rows: string[][] = [];
    for (const { example, source } of HAND_WRITTEN_VOLUME)
      rows.push(
        await benchScene(gpu, example, scenes[example]!, source, rounds, 'volume-probe', opacityDiffer),
      );
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
