/**
 * 3D sphere tracer speed (part of `npm run bench`; alone: `npx tsx tests/bench/trace3d.ts [rounds]`):
 * for each example with a hand-written tracer (tests/bench/hand-written/trace3d.ts — written for
 * speed for that one picture, not a copy of the generated algorithm), ms per frame at 512² on
 * SwiftShader of the generated uniform program (U), the generated baked one (B) and the hand-written
 * one (H), probe output, INTERLEAVED (U B H U B H …), each frame ended by readPixels; the ratios are
 * medians of per-round ratios, and "hit/miss differ" is the fraction of pixels where B and H disagree
 * on hit or miss. Plus one colour frame of each generated program (normals, occlusion, shadow).
 * Prints figures, never fails on a time. Goal (issue #22): ≤ 1.25× (stretch 1.10×), < 1 % differ.
 */
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { cameraUniforms, compile3d, type Variant3d } from '../../shader-gen/space/compile-3d.ts';
import { GpuProbe } from '../parity/gpu-probe.ts';
import { exampleScenes3d } from '../shader-gen/space/scenes-3d.ts';
import { HAND_WRITTEN_3D, type HandWrittenTracer } from './hand-written/trace3d.ts';
import { FRAME_SIZE, median, medianRatio, printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';

export const ROUNDS = 5;
const ms = (x: number) => x.toFixed(0);
const times = (x: number) => `${x.toFixed(2)}×`;

/** Fraction of pixels where two probe images disagree on hit/miss (channel 0). */
export function hitMissDiffer(a: Float32Array, b: Float32Array): number {
  let differ = 0;
  for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i]) differ++;
  return differ / (a.length / 4);
}

/**
 * One row: U, B and H interleaved for `rounds`, medians, ratios, how many pixels B and H differ on
 * (`differ`), and one colour frame. `variant` is the generated program's probe output ('probe' for
 * the tracer, 'volume-probe' for the volume renderer, volume3d.ts).
 */
export async function benchScene(
  gpu: GpuProbe,
  name: string,
  scene: Scene3d,
  hand: string,
  rounds: number,
  variant: Variant3d = 'probe',
  differ: (a: Float32Array, b: Float32Array) => number = hitMissDiffer,
) {
  const camera = cameraUniforms(scene.camera);
  const u = compile3d(scene, { variant });
  const b = compile3d(scene, { variant, bake: true });
  const programs = {
    uniform: { index: await gpu.program(u.vertexSource, u.source), uniforms: [...u.uniforms, ...camera] },
    baked: { index: await gpu.program(b.vertexSource, b.source), uniforms: [...b.uniforms, ...camera] },
    hand: { index: await gpu.program(u.vertexSource, hand), uniforms: camera },
  };
  const frame = (p: (typeof programs)['hand']) =>
    gpu.render(p.index, p.uniforms, { center: [0, 0], scale: 1 });
  // One warm-up frame each (SwiftShader finishes its JIT on the first draw); B and H kept to compare.
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
    `${(100 * differ(bakedImage.data, handImage.data)).toFixed(2)} %`,
    ms(colourMs),
  ];
}

/** A table of benchScene rows: each hand-written program against the generated ones. */
export interface HandBench {
  readonly tracers: readonly HandWrittenTracer[];
  /** What the table compares, printed above it after the frame size and renderer. */
  readonly title: string;
  /** The rest of the heading, after the rounds. */
  readonly notes: string;
  readonly differLabel: string;
  readonly variant?: Variant3d;
  readonly differ?: (a: Float32Array, b: Float32Array) => number;
}

/** Runs benchScene for every tracer of `bench` on one probe page and prints the table. */
export async function runHandBench(bench: HandBench, rounds: number): Promise<void> {
  const gpu = await GpuProbe.open(FRAME_SIZE, FRAME_SIZE);
  try {
    const scenes = exampleScenes3d();
    const rows: string[][] = [];
    for (const { example, source } of bench.tracers)
      rows.push(
        await benchScene(gpu, example, scenes[example]!, source, rounds, bench.variant, bench.differ),
      );
    console.log(
      `\n${bench.title}, ${FRAME_SIZE}², Chromium WebGL2 (${gpu.renderer}), ${rounds} interleaved rounds ` +
        `(U B H …), ${bench.notes}\n`,
    );
    printTable(
      [
        'example',
        'uniform ms',
        'baked ms',
        'hand ms',
        'baked/hand',
        'uniform/hand',
        bench.differLabel,
        'colour ms',
      ],
      rows,
    );
  } finally {
    await gpu.close();
  }
}

export const run = (rounds = ROUNDS): Promise<void> =>
  runHandBench(
    {
      tracers: HAND_WRITTEN_3D,
      title: '3D sphere tracer against hand-written tracers written for speed',
      notes:
        'probe output; colour = one shaded baked frame. Goal: generated/hand ≤ 1.25×, hit/miss differ < 1 %.',
      differLabel: 'hit/miss differ',
    },
    rounds,
  );

runWhenMain(import.meta.url, run, ROUNDS);
