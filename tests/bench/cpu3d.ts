/**
 * CPU 3D still speed (part of `npm run bench`; alone: `npx tsx tests/bench/cpu3d.ts [size]`): the
 * Fig. 26 quasi-sphere and the Fig. 27 tiling steps (the tile seed with max iterations 2, where the
 * budget bound of docs/math-3d.md "The bound when the budget runs out" does the work) (examples/3d)
 * through `kleinflow render`'s 3D path (render-3d-pool.ts) at
 * a reduced size, 1 sample/px, on this thread and then on a worker thread per core (their start-up
 * included, as a user pays it), and what each projects to for 1024², 4 samples/px: time scales
 * with pixels × samples. The goal (issue #22) is ≤ 3 min for that on a 2-core machine. Prints
 * figures, never fails on a time.
 */
import { readFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { EXAMPLES_3D_DIR, examplePath } from '../../src/cli/examples.ts';
import { renderScene3dOnPool } from '../../src/cli/render-3d-pool.ts';
import { formatDuration } from '../../src/cli/render-estimate.ts';
import { printTable } from './report.ts';
import { runWhenMain } from './run-when-main.ts';

export const SIZE = 256;
/** The figure the goal is about: 1024², 4 samples/px, at most 3 minutes. */
const GOAL = { side: 1024, samples: 4, seconds: 180 };

/** The examples timed: the quasi-sphere the goal is about, and the tile seed's tiling steps. */
const EXAMPLES = ['fig26-quasi-sphere', 'fig27-tiling-steps'];

function exampleScene(name: string) {
  const text = readFileSync(examplePath(name, EXAMPLES_3D_DIR), 'utf8');
  const loaded = parseDocumentText(text, registry);
  if (!loaded.ok) throw new Error(`${name} does not load`);
  const scene = evaluateGraph(loaded.doc, registry).scene3d;
  if (!scene) throw new Error(`${name} has no 3D scene`);
  return scene;
}

export async function run(size = SIZE): Promise<void> {
  for (const name of EXAMPLES) await runExample(name, size);
}

async function runExample(name: string, size: number): Promise<void> {
  const scene = exampleScene(name);
  const cores = availableParallelism();
  const timed = async (threads: number) => {
    const started = performance.now();
    await renderScene3dOnPool(scene, { width: size, height: size, samples: 1, threads });
    return performance.now() - started;
  };
  const scale = ((GOAL.side * GOAL.side) / (size * size)) * GOAL.samples;
  const row = (label: string, ms: number) => [
    label,
    ms.toFixed(0),
    formatDuration((ms * scale) / 1000),
    (ms * scale) / 1000 <= GOAL.seconds ? 'yes' : 'no',
  ];
  const one = await timed(1);
  const all = await timed(cores);
  console.log(
    `\nCPU 3D still, ${name}, ${size}², 1 sample/px (kleinflow render); projected to ` +
      `${GOAL.side}², ${GOAL.samples} samples/px; goal ≤ ${formatDuration(GOAL.seconds)}. ` +
      `Speed-up on ${cores} threads ×${(one / all).toFixed(2)}.\n`,
  );
  printTable(
    ['threads', 'ms', `projected ${GOAL.side}² ×${GOAL.samples}`, 'within goal'],
    [row('1', one), row(String(cores), all)],
  );
}

runWhenMain(import.meta.url, run, SIZE, 8);
