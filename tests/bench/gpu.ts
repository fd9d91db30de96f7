/**
 * GPU benchmark (part of `npm run bench`; tests/bench/run.ts imports this and calls run()): per
 * example, in one Chromium session, compile+link time, frame time at 512² of the uniform and the
 * baked program (and of the hand-written shader where one exists, against the generated probe
 * variant it mirrors), and the latency of a structural and of a value edit. Prints a table; never
 * fails on a time. Compare ratios within one run, never absolute times across runs or machines.
 */
import { readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { exampleScene } from '../src/viewport/fixtures.ts';
import { withBenchPage } from './bench-page.ts';
import type { GpuBenchResult } from './gpu-page.ts';
import { printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';

/** Frames per median (the brief asks for at least 5). */
const FRAMES = 5;

async function handWritten(): Promise<Map<string, string>> {
  try {
    const { HAND_WRITTEN } = await import('./hand-written/index.ts');
    return new Map(HAND_WRITTEN.map((h) => [h.example, h.source]));
  } catch (e) {
    console.log(`(no hand-written shaders: ${(e as Error).message})`);
    return new Map();
  }
}

const ms = (x: number) => (x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(1) : x.toFixed(2));
const ratio = (a: number, b: number) => `${(a / b).toFixed(2)}×`;

function row(name: string, elements: number, r: GpuBenchResult): string[] {
  return [
    name,
    String(elements),
    ms(r.compileUniformMs),
    ms(r.firstFrameUniformMs),
    ms(r.compileBakedMs),
    ms(r.frameUniformMs),
    ms(r.frameBakedMs),
    ratio(r.frameUniformMs, r.frameBakedMs),
    r.probe ? `${ratio(r.probe.bakedMs, r.probe.handMs)} / ${ratio(r.probe.uniformMs, r.probe.handMs)}` : '–',
    ms(r.structuralEditMs),
    ms(r.valueEditMs),
  ];
}

const HEADER = [
  'example',
  'elems',
  'compile+link ms',
  '1st frame',
  'baked compile',
  'frame ms',
  'baked frame',
  'baked speed-up',
  'vs hand (baked / uniform)',
  'struct edit ms',
  'value edit ms',
];

export async function run(): Promise<void> {
  const examplesDir = fileURLToPath(new URL('../../examples/', import.meta.url));
  const names = readdirSync(examplesDir)
    .filter((f) => f.endsWith('.kleinflow.json'))
    .map((f) => f.slice(0, -'.kleinflow.json'.length))
    .sort();
  const hand = await handWritten();
  await withBenchPage(async (page) => {
    console.log(`\nGPU (WebGL2): ${await page.evaluate(() => window.kfBench.renderer())}`);
    console.log(
      [
        `512² frames, median of ${FRAMES}, each ended by readPixels. 1st frame: the first draw after linking`,
        '(drivers may finish compiling there). "vs hand": generated probe ÷ hand-written probe frame time.',
        'struct edit: generate + compile + link + first frame; value edit: generate + upload + frame.\n',
      ].join('\n'),
    );
    const rows: string[][] = [];
    for (const name of names) {
      try {
        const scene = exampleScene(name);
        const r = await page.evaluate(([s, h, n]) => window.kfBench.measure(s, h, n), [
          scene,
          hand.get(name) ?? null,
          FRAMES,
        ] as const);
        rows.push(row(name, scene.elements.length, r));
      } catch (e) {
        rows.push([
          name,
          '?',
          `failed: ${(e as Error).message.split('\n')[0]}`,
          ...HEADER.slice(3).map(() => ''),
        ]);
      }
    }
    printTable(HEADER, rows);
    for (const name of hand.keys()) {
      if (!names.includes(name)) console.log(`(hand-written shader for ${name}: no such example, skipped)`);
    }
    if (hand.size === 0)
      console.log('(hand-written comparison skipped: tests/bench/hand-written/ is absent)');
  });
}

runWhenMain(import.meta.url, () => run());
