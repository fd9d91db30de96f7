/**
 * CPU volume renderer speed (part of `npm run bench`; alone: `npx tsx tests/bench/cpu-volume.ts
 * [size]`): the Fig. 10 example through the generated CPU path (shader-gen/space/render-3d.ts, one
 * thread, 1 sample/px) against the hand-written renderer for that picture
 * (tests/bench/hand-written/fig10-volume-cpu.ts), interleaved, with the fraction of pixels whose
 * bytes differ by more than 2. Prints figures, never fails on a time.
 */
import { renderScene3d } from '../../shader-gen/space/render-3d.ts';
import { exampleScenes3d } from '../shader-gen/space/scenes-3d.ts';
import { renderFig10Volume } from './hand-written/fig10-volume-cpu.ts';
import { median, medianRatio, printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';

export const SIZE = 96;
const ROUNDS = 3;

/** Fraction of pixels where some channel differs by more than `tolerance` (of 255). */
export function bytesDiffer(a: Uint8ClampedArray, b: Uint8ClampedArray, tolerance = 2): number {
  let differ = 0;
  for (let i = 0; i < a.length; i += 4)
    if ([0, 1, 2].some((k) => Math.abs(a[i + k]! - b[i + k]!) > tolerance)) differ++;
  return differ / (a.length / 4);
}

export async function run(size = SIZE): Promise<void> {
  const scene = exampleScenes3d()['fig10-volume-nesting-spheres']!;
  const t = { generated: [] as number[], hand: [] as number[] };
  let generated: Uint8ClampedArray<ArrayBufferLike> = new Uint8ClampedArray(0);
  let hand: Uint8ClampedArray<ArrayBufferLike> = new Uint8ClampedArray(0);
  for (let r = 0; r < ROUNDS; r++) {
    let start = performance.now();
    generated = renderScene3d(scene, size, size, { samples: 1 }).data;
    t.generated.push(performance.now() - start);
    start = performance.now();
    hand = renderFig10Volume(size, size, scene.camera, scene.background);
    t.hand.push(performance.now() - start);
  }
  console.log(
    `\nCPU volume renderer, Fig. 10 example, ${size}², 1 sample/px, one thread, ${ROUNDS} interleaved rounds, ` +
      'against a hand-written renderer for that picture.\n',
  );
  printTable(
    ['example', 'generated ms', 'hand ms', 'generated/hand', 'pixels differ'],
    [
      [
        'fig10-volume-nesting-spheres',
        median(t.generated).toFixed(0),
        median(t.hand).toFixed(0),
        `${medianRatio(t.generated, t.hand).toFixed(2)}×`,
        `${(100 * bytesDiffer(generated, hand)).toFixed(2)} %`,
      ],
    ],
  );
}

runWhenMain(import.meta.url, run, SIZE, 8);
