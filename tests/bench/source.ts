/**
 * Shader source per frame: while the user drags, the viewport generates the uniform program's
 * source for every new scene and looks the program up by that text (src/viewport/program-cache.ts
 * keys on it, so there is no hand-kept "structure key"). This prints what that costs per frame:
 * compile() of each example's scene plus the Map lookup by the source, median of RUNS after
 * WARMUP untimed runs, and the largest scene the element cap allows (generated, see scale.ts).
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import { compile } from '../../shader-gen/compile.ts';
import { exampleNames, loadExample } from '../support/examples.ts';
import { median, printTable } from './report.ts';
import { scaleGraph } from './scale.ts';

const RUNS = 41;
const WARMUP = 10;

/** Median ms of generating the source and finding its program in a cache keyed by source. */
function msPerFrame(scene: Scene): { ms: number; chars: number } {
  const cache = new Map<string, number>([[compile(scene).source, 1]]);
  const once = () => cache.get(compile(scene).source);
  for (let i = 0; i < WARMUP; i++) once();
  const times: number[] = [];
  for (let i = 0; i < RUNS; i++) {
    const t0 = performance.now();
    if (once() !== 1) throw new Error('the same scene gave a different source');
    times.push(performance.now() - t0);
  }
  return { ms: median(times), chars: compile(scene).source.length };
}

export async function run(): Promise<void> {
  console.log(`\nShader source per frame (compile() + program lookup by source), median of ${RUNS}`);
  const scenes: [string, Scene][] = exampleNames().map((name) => [name, loadExample(name).scene]);
  scenes.push(['scale-5000 (element cap)', evaluateGraph(scaleGraph(5_000), registry).scene]);
  const rows = scenes.map(([name, scene]) => {
    const { ms, chars } = msPerFrame(scene);
    return [name, String(scene.elements.length), String(chars), ms.toFixed(3)];
  });
  printTable(['scene', 'elements', 'source chars', 'ms / frame'], rows);
  const examples = rows.slice(0, -1).map((r) => Number(r[3]));
  console.log(
    `  examples: median ${median(examples).toFixed(3)} ms, max ${Math.max(...examples).toFixed(3)} ms per frame`,
  );
}
