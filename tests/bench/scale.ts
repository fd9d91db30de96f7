/**
 * Graph scale: generated graphs of 100, 1,000 and 5,000 nodes with a realistic mix (points →
 * lines and circles → reflections and inversions → one render node, plus chains of number nodes
 * driving the radii). Prints the median of RUNS timings for load (parse + validate), evaluation
 * and compiling the resulting scene. The target for evaluating 1,000 nodes is 5 ms; like every
 * bench it reports and never fails.
 */
import { LIMITS } from '../../nodes/core/scene.ts';
import type { GraphDoc, GraphEdge, GraphNode } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { compile } from '../../shader-gen/compile.ts';
import { median } from './report.ts';

const RUNS = 15;
/** Untimed runs first, so the JIT has compiled the hot paths (an editor evaluates on every drag). */
const WARMUP = 5;
const SIZES = [100, 1_000, 5_000] as const;
/** Evaluating this many nodes should take under TARGET_MS. */
const TARGET = { nodes: 1_000, ms: 5 } as const;

/** Nodes per generated block (see scaleGraph). */
const BLOCK = 10;

/**
 * Exactly `nodes` nodes in blocks of ten (and a few loose numbers to make up the count): points P, Q, R; line PQ → reflection; numbers n1 → n2 →
 * n3 (a chain, n3 the radius) and circle (R, n3) → inversion; both elements into the render node.
 * Blocks sit on a spiral so no two mirrors coincide.
 */
export function scaleGraph(nodes: number): GraphDoc {
  const out: GraphNode[] = [];
  const edges: GraphEdge[] = [];
  const add = (id: string, type: string, params: Record<string, unknown> = {}) =>
    out.push({ id, type, position: [0, 0], params });
  const wire = (from: string, to: string) => {
    const [fn, fp] = from.split('.');
    const [tn, tp] = to.split('.');
    edges.push({ id: `e${edges.length}`, from: { node: fn, port: fp }, to: { node: tn, port: tp } });
  };
  const blocks = Math.max(1, Math.floor((nodes - 1) / BLOCK));
  for (let b = 0; b < blocks; b++) {
    const t = b * 0.7;
    const [x, y] = [Math.cos(t) * (1 + b * 0.01), Math.sin(t) * (1 + b * 0.01)];
    add(`p${b}`, 'point', { x, y });
    add(`q${b}`, 'point', { x: x + 0.3, y: y + 0.1 });
    add(`r${b}`, 'point', { x: x * 3, y: y * 3 });
    add(`l${b}`, 'line');
    wire(`p${b}.point`, `l${b}.a`);
    wire(`q${b}.point`, `l${b}.b`);
    add(`m${b}`, 'reflection');
    wire(`l${b}.line`, `m${b}.line`);
    add(`n${b}a`, 'number', { value: 0.05 });
    add(`n${b}b`, 'number');
    add(`n${b}c`, 'number');
    wire(`n${b}a.value`, `n${b}b.value`);
    wire(`n${b}b.value`, `n${b}c.value`);
    add(`c${b}`, 'circle');
    wire(`r${b}.point`, `c${b}.center`);
    wire(`n${b}c.value`, `c${b}.radius`);
    add(`i${b}`, 'inversion');
    wire(`c${b}.circle`, `i${b}.circle`);
    wire(`m${b}.element`, 'out.elements');
    wire(`i${b}.element`, 'out.elements');
  }
  // Pad with loose number nodes to exactly `nodes` (the render node included).
  for (let i = out.length + 1; i < nodes; i++) add(`pad${i}`, 'number', { value: i });
  add('out', 'render', { maxIterations: 50 });
  return {
    format: 'kleinflow',
    version: 1,
    meta: { title: `scale ${nodes}` },
    nodes: out,
    edges,
    view: { center: [0, 0], scale: 8 },
  };
}

/** Median wall-clock and CPU milliseconds of RUNS calls (CPU time is steadier on a shared machine). */
function time(fn: () => void): { wall: number; cpu: number } {
  const wall: number[] = [];
  const cpu: number[] = [];
  for (let i = 0; i < WARMUP; i++) fn();
  for (let i = 0; i < RUNS; i++) {
    const c0 = process.cpuUsage();
    const t0 = performance.now();
    fn();
    wall.push(performance.now() - t0);
    const c = process.cpuUsage(c0);
    cpu.push((c.user + c.system) / 1000);
  }
  return { wall: median(wall), cpu: median(cpu) };
}

export interface ScaleRow {
  readonly nodes: number;
  readonly edges: number;
  readonly elements: number;
  readonly load: { wall: number; cpu: number };
  readonly evaluate: { wall: number; cpu: number };
  readonly compile: { wall: number; cpu: number };
}

export function measure(nodes: number): ScaleRow {
  const doc = scaleGraph(nodes);
  const text = JSON.stringify(doc);
  const loaded = parseDocumentText(text, registry);
  if (!loaded.ok) throw new Error(`generated graph does not load: ${loaded.diagnostics[0].message}`);
  const first = evaluateGraph(loaded.doc, registry);
  const errors = first.diagnostics.filter((d) => d.severity === 'error');
  if (errors.length > 0) throw new Error(`generated graph has errors: ${errors[0].message}`);
  const scene = first.scene;
  return {
    nodes: loaded.doc.nodes.length,
    edges: loaded.doc.edges.length,
    elements: scene.elements.length,
    load: time(() => parseDocumentText(text, registry)),
    evaluate: time(() => evaluateGraph(loaded.doc, registry)),
    compile: time(() => compile(scene)),
  };
}

const ms = (t: { wall: number; cpu: number }) => `${t.wall.toFixed(2)} (${t.cpu.toFixed(2)})`.padStart(15);

export async function run(): Promise<void> {
  console.log(
    `\nGraph scale: median of ${RUNS} runs, wall ms (CPU ms); scene capped at ${LIMITS.maxElements} elements`,
  );
  console.log(
    `${'nodes  edges  elements'} ${'load'.padStart(15)} ${'evaluate'.padStart(15)} ${'compile'.padStart(15)}`,
  );
  for (const n of SIZES) {
    const r = measure(n);
    const cols = [r.nodes, r.edges, r.elements].map((v, i) => String(v).padStart([5, 6, 9][i]));
    console.log(`${cols.join(' ')} ${ms(r.load)} ${ms(r.evaluate)} ${ms(r.compile)}`);
    if (n === TARGET.nodes) {
      const verdict = r.evaluate.cpu < TARGET.ms ? 'within' : 'OVER';
      console.log(`       (evaluating ${n} nodes: ${verdict} the ${TARGET.ms} ms target, by CPU time)`);
    }
  }
}

// Run directly: `npx tsx tests/bench/scale.ts`.
if (import.meta.url === `file://${process.argv[1]}`) void run();
