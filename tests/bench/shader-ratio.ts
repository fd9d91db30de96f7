/**
 * Generated vs hand-written shader speed (part of `npm run bench`; run alone with
 * `npx tsx tests/bench/shader-ratio.ts [rounds]`). For every example with hand-written probe
 * shaders (tests/bench/hand-written/), one Chromium session renders four programs at 512²,
 * INTERLEAVED (U B H HU U B H HU …) for ROUNDS rounds, each frame ended by readPixels: the generated
 * uniform program (U), the generated baked one (B), the hand-written one with constants (H) and the
 * hand-written one with the values as uniforms (HU). Prints the median frame times and the ratios
 * (medians of the per-round ratios: each round's frames ran under the same machine load):
 * baked/hand and uniform/hand-uniform compare like with like; uniform/hand shows what values as
 * uniforms cost at all on this renderer (SwiftShader folds constants into its machine code and
 * reloads uniforms, so no uniform shader, hand-written or generated, comes near the constant one
 * there). Never fails on a time; compare ratios, not absolute times.
 */
import { compile } from '../../shader-gen/compile.ts';
import { exampleScene } from '../src/viewport/fixtures.ts';
import { withBenchPage } from './bench-page.ts';
import { HAND_WRITTEN } from './hand-written/index.ts';
import { median, medianRatio, printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';

/** Rounds of U B H HU frames (a ratio moves by about ±0.02 between runs at 25–31 rounds here). */
export const ROUNDS = 31;

const ms = (x: number) => x.toFixed(1);
const times = (x: number) => `${x.toFixed(2)}×`;

const HEADER = [
  'example',
  'uniform ms',
  'baked ms',
  'hand ms',
  'hand-uniform ms',
  'baked/hand',
  'uniform/hand-uniform',
  'uniform/hand',
];

export async function run(rounds = ROUNDS): Promise<void> {
  await withBenchPage(async (page) => {
    console.log(
      `\nGenerated vs hand-written probe shaders, 512², ${rounds} interleaved rounds (U B H HU …), ` +
        'each frame ended by readPixels; ratios are medians of the per-round ratios.\n' +
        'hand = values as constants; hand-uniform = the same shader reading the values from uniforms.\n',
    );
    const rows: string[][] = [];
    for (const { example, source, uniformSource } of HAND_WRITTEN) {
      const scene = exampleScene(example);
      const uniform = compile(scene, { variant: 'probe' });
      const baked = compile(scene, { variant: 'probe', baked: true });
      const programs = {
        uniform: { vertex: uniform.vertexSource, fragment: uniform.source, uniforms: uniform.uniforms },
        baked: { vertex: baked.vertexSource, fragment: baked.source, uniforms: baked.uniforms },
        hand: { vertex: uniform.vertexSource, fragment: source, uniforms: [] },
        handUniform: { vertex: uniform.vertexSource, fragment: uniformSource, uniforms: uniform.uniforms },
      };
      const t = await page.evaluate(([s, p, n]) => window.kfBench.interleaved(s, p, n), [
        scene,
        programs,
        rounds,
      ] as const);
      const perRound = (a: string, b: string) => medianRatio(t[a], t[b]);
      rows.push([
        example,
        ms(median(t.uniform)),
        ms(median(t.baked)),
        ms(median(t.hand)),
        ms(median(t.handUniform)),
        times(perRound('baked', 'hand')),
        times(perRound('uniform', 'handUniform')),
        times(perRound('uniform', 'hand')),
      ]);
    }
    printTable(HEADER, rows);
  });
}

runWhenMain(import.meta.url, run, ROUNDS);
