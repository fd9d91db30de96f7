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
import { HAND_WRITTEN_VOLUME } from './hand-written/trace3d.ts';
import { runWhenMain } from './run-when-main.ts';
import { runHandBench } from './trace3d.ts';

export const ROUNDS = 5;

/** Fraction of pixels whose channel-0 opacity differs by more than `tolerance`. */
export function opacityDiffer(a: Float32Array, b: Float32Array, tolerance = 0.02): number {
  let differ = 0;
  for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i]! - b[i]!) > tolerance) differ++;
  return differ / (a.length / 4);
}

export const run = (rounds = ROUNDS): Promise<void> =>
  runHandBench(
    {
      tracers: HAND_WRITTEN_VOLUME,
      title: 'Volume renderer (Fig. 10) against a hand-written one written for speed',
      notes: 'volume probe output; colour = one baked colour frame.',
      differLabel: 'opacity differ',
      variant: 'volume-probe',
      differ: opacityDiffer,
    },
    rounds,
  );

runWhenMain(import.meta.url, run, ROUNDS);
