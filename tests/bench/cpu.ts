/**
 * CPU interpreter throughput per example: the IIS loop (runIis, exactly what the CLI renders
 * with) over a 512² grid of pixel centres at the example's view, one sample, on one core.
 * points/s is the median of RUNS timed passes; element tests/s multiplies it by the mean number
 * of element inside-tests per point, counted in a separate pass on a 128² grid with counting
 * wrappers (so the timed loop runs the real, unwrapped code).
 */
import { readFileSync } from 'node:fs';
import type { Scene } from '../../nodes/core/scene.ts';
import { pixelToWorld } from '../../nodes/core/view.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import type { CpuElement, IisState } from '../../shader-gen/elements/element-kind.ts';
import { type PreparedElements, prepare, runIis } from '../../shader-gen/interpret.ts';
import { exampleNames, examplePath } from '../../src/cli/examples.ts';
import { median } from './report.ts';

const GRID = 512;
const COUNT_GRID = 128;
const RUNS = 3;

export interface CpuBenchRow {
  readonly name: string;
  readonly elements: number;
  readonly pointsPerSecond: number;
  readonly testsPerPoint: number;
  readonly meanDepth: number;
}

/** Runs the loop at every pixel centre of a size² grid; returns the summed depth. */
function sweep(scene: Scene, prepared: PreparedElements, size: number): number {
  const st: IisState = { x: 0, y: 0, s: 1, depth: 0 };
  let depthSum = 0;
  for (let py = 0; py < size; py++) {
    for (let px = 0; px < size; px++) {
      const [x, y] = pixelToWorld(scene.view, size, size, px, py);
      st.x = x;
      st.y = y;
      st.s = 1;
      st.depth = 0;
      runIis(prepared, scene.maxIterations, st);
      depthSum += st.depth;
    }
  }
  return depthSum;
}

/** The same elements with kinds that count every inside-test (step or inside call). */
function counting(prepared: PreparedElements): { prepared: PreparedElements; count: () => number } {
  let n = 0;
  const kinds = prepared.kinds.map(
    (k): CpuElement => ({
      ...k,
      step: (e, st) => {
        n++;
        return k.step(e, st);
      },
      inside: (e, x, y) => {
        n++;
        return k.inside(e, x, y);
      },
    }),
  );
  return { prepared: { elements: prepared.elements, kinds }, count: () => n };
}

export function benchExample(name: string): CpuBenchRow {
  const loaded = parseDocumentText(readFileSync(examplePath(name), 'utf8'), registry);
  if (!loaded.ok) throw new Error(`${name} does not load`);
  const { scene } = evaluateGraph(loaded.doc, registry);
  const prepared = prepare(scene.elements);
  const times: number[] = [];
  let depthSum = 0;
  for (let i = 0; i < RUNS; i++) {
    const t = performance.now();
    depthSum = sweep(scene, prepared, GRID);
    times.push(performance.now() - t);
  }
  const counter = counting(prepared);
  sweep(scene, counter.prepared, COUNT_GRID);
  return {
    name,
    elements: scene.elements.length,
    pointsPerSecond: (GRID * GRID) / (median(times) / 1000),
    testsPerPoint: counter.count() / (COUNT_GRID * COUNT_GRID),
    meanDepth: depthSum / (GRID * GRID),
  };
}

const si = (v: number) =>
  v >= 1e9
    ? `${(v / 1e9).toFixed(2)} G`
    : v >= 1e6
      ? `${(v / 1e6).toFixed(2)} M`
      : `${(v / 1e3).toFixed(1)} k`;

export async function run(): Promise<void> {
  console.log(`\nCPU interpreter (one core, ${GRID}² pixel centres, 1 sample, median of ${RUNS})`);
  console.log(
    `${'example'.padEnd(24)} ${'elems'.padStart(5)} ${'depth'.padStart(7)} ${'tests/pt'.padStart(9)} ${'points/s'.padStart(11)} ${'tests/s'.padStart(11)}`,
  );
  for (const name of exampleNames()) {
    const r = benchExample(name);
    console.log(
      `${r.name.padEnd(24)} ${String(r.elements).padStart(5)} ${r.meanDepth.toFixed(1).padStart(7)} ${r.testsPerPoint.toFixed(1).padStart(9)} ${si(r.pointsPerSecond).padStart(11)} ${si(r.pointsPerSecond * r.testsPerPoint).padStart(11)}`,
    );
  }
}
