/**
 * The colour pipeline's speed (part of `npm run bench`; alone: `npx tsx tests/bench/colour-ratio.ts
 * [rounds]`). For every example whose hand-written shader also draws its picture (`colour` in
 * tests/bench/hand-written/), one Chromium session renders, at 512² and one sample per pixel,
 * INTERLEAVED for ROUNDS rounds: the generated colour programs with uniforms (U) and baked (B), the
 * one-sample Shadertoy export in Shadertoy's wrapper (T), and the hand-written colour shader
 * writing linear light (H, what B is compared with) and writing sRGB as is (HS, what T is compared
 * with). Ratios are medians of per-round ratios. Before timing, each pair compared is rendered once
 * and its pictures compared in 8-bit sRGB levels (the max difference and the share of pixels beyond
 * rounding are printed): a ratio only means something at equal output. Never fails on a time.
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { compile, shadertoySource } from '../../shader-gen/compile.ts';
import { shadertoyWrapper } from '../shader-gen/support/glslang.ts';
import { exampleScene } from '../src/viewport/fixtures.ts';
import { withBenchPage } from './bench-page.ts';
import type { OutputDifference, OutputProgram } from './gpu-page.ts';
import { HAND_WRITTEN, withDefines } from './hand-written/index.ts';
import { FRAME_SIZE, median, medianRatio, printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';
import { ROUNDS } from './shader-ratio.ts';

const ms = (x: number) => x.toFixed(1);
const times = (x: number) => `${x.toFixed(2)}×`;
const diff = (d: OutputDifference) => `${d.maxLevels} (${(d.beyondRounding * 100).toFixed(2)} %)`;

/** The five programs of one scene, all at one sample per pixel. */
function programs(scene: Scene, handSource: string): Record<string, OutputProgram> {
  const one = { ...scene, samples: 1 };
  const uniform = compile(one);
  const baked = compile(one, { baked: true });
  const vertex = uniform.vertexSource;
  return {
    uniform: { vertex, fragment: uniform.source, uniforms: uniform.uniforms, linear: true },
    baked: { vertex, fragment: baked.source, uniforms: [], linear: true },
    hand: { vertex, fragment: withDefines(handSource, 'COLOUR'), uniforms: [], linear: true },
    shadertoy: {
      vertex,
      fragment: shadertoyWrapper(shadertoySource(one)),
      uniforms: [{ name: 'iResolution', type: 'vec3', value: [FRAME_SIZE, FRAME_SIZE, 1] }],
      linear: false,
    },
    handSrgb: {
      vertex,
      fragment: withDefines(handSource, 'COLOUR', 'SRGB_OUTPUT'),
      uniforms: [],
      linear: false,
    },
  };
}

/** The pairs whose pictures must agree, in the order of the table's Δ columns. */
const PAIRS = [
  ['baked', 'hand'],
  ['shadertoy', 'handSrgb'],
  ['uniform', 'baked'],
] as const;

const HEADER = [
  'example',
  'uniform ms',
  'baked ms',
  'shadertoy ms',
  'hand ms',
  'hand sRGB ms',
  'baked/hand',
  'shadertoy/hand sRGB',
  'uniform/baked',
  ...PAIRS.map(([a, b]) => `Δ ${a}|${b}`),
];

export async function run(rounds = ROUNDS): Promise<void> {
  await withBenchPage(async (page) => {
    console.log(
      `\nColour pipeline: generated vs hand-written colour shaders, 512², one sample per pixel, ${rounds} ` +
        'interleaved rounds (U B T H HS …); ratios are medians of the per-round ratios.\n' +
        'hand = linear-light output (as the baked program, for accumulation); hand sRGB = sRGB written as is ' +
        '(as the one-sample Shadertoy export).\n' +
        'Δ a|b: largest difference between the two pictures in 8-bit sRGB levels (share of pixels beyond ' +
        'one level of rounding).\n',
    );
    const rows: string[][] = [];
    for (const { example, source, colour } of HAND_WRITTEN) {
      if (!colour) continue;
      const scene = exampleScene(example);
      const p = programs(scene, source);
      const deltas = await page.evaluate(([s, q, pairs]) => window.kfBench.outputDifferences(s, q, pairs), [
        scene,
        p,
        PAIRS,
      ] as const);
      const t = await page.evaluate(([s, q, n]) => window.kfBench.interleaved(s, q, n), [
        scene,
        p,
        rounds,
      ] as const);
      rows.push([
        example,
        ms(median(t.uniform)),
        ms(median(t.baked)),
        ms(median(t.shadertoy)),
        ms(median(t.hand)),
        ms(median(t.handSrgb)),
        times(medianRatio(t.baked, t.hand)),
        times(medianRatio(t.shadertoy, t.handSrgb)),
        times(medianRatio(t.uniform, t.baked)),
        ...deltas.map(diff),
      ]);
    }
    printTable(HEADER, rows);
  });
}

runWhenMain(import.meta.url, run, ROUNDS);
