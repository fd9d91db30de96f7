/**
 * The robustness contract of the non-UI pipeline, checked on one input: load (parse → migrate →
 * validate) → evaluate → compile (uniform and baked) never throws, a loaded document can be
 * serialized and cloned (save, share, undo), and every diagnostic says where
 * the problem is (a document path or a node id) in a message of readable length. Whatever reaches
 * the scene or the uniforms is a finite number. Returns the problems found (empty = fine) and
 * the time the whole pipeline took, so callers can guard against hangs.
 */
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import { LIMITS, type Scene } from '../../nodes/core/scene.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { loadDocument, parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { compile } from '../../shader-gen/compile.ts';

/** A message longer than this is not something a person can read (e.g. a 10 MB string echoed back). */
export const MAX_MESSAGE_CHARS = 2_000;

export interface PipelineReport {
  readonly problems: string[];
  readonly ms: number;
  /** How far it got: 'load' (refused), 'evaluate' (no render node / empty scene) or 'compile'. */
  readonly stage: 'load' | 'evaluate' | 'compile';
  readonly diagnostics: readonly Diagnostic[];
  readonly scene?: Scene;
  /** Uniform values beyond LIMITS.gpuMaxMagnitude (finite here, overflowing on the GPU). */
  readonly beyondGpu: string[];
}

/** Every number inside `value` (any depth, iteratively) that is not finite, by path. */
export function nonFiniteNumbers(value: unknown, root = '$'): string[] {
  const bad: string[] = [];
  const stack: [unknown, string][] = [[value, root]];
  while (stack.length > 0) {
    const [v, path] = stack.pop()!;
    if (typeof v === 'number') {
      if (!Number.isFinite(v)) bad.push(`${path} = ${v}`);
    } else if (Array.isArray(v)) {
      for (let i = 0; i < v.length; i++) stack.push([v[i], `${path}[${i}]`]);
    } else if (v !== null && typeof v === 'object')
      for (const [k, x] of Object.entries(v)) stack.push([x, `${path}.${k}`]);
  }
  return bad;
}

function checkDiagnostics(where: string, ds: readonly Diagnostic[], problems: string[]): void {
  for (const d of ds) {
    const text = `${d.code} ${d.message.slice(0, 200)}`;
    if (!d.path && !d.nodeId) problems.push(`${where}: diagnostic names neither a path nor a node: ${text}`);
    if (typeof d.message !== 'string' || d.message.length === 0)
      problems.push(`${where}: empty message: ${text}`);
    else if (d.message.length > MAX_MESSAGE_CHARS)
      problems.push(`${where}: message of ${d.message.length} characters: ${text}`);
  }
}

/** Runs the whole pipeline on JSON text (string) or an already parsed value. */
export function checkPipeline(input: { text: string } | { value: unknown }): PipelineReport {
  const problems: string[] = [];
  const beyondGpu: string[] = [];
  const t0 = performance.now();
  const elapsed = () => performance.now() - t0;
  let stage: PipelineReport['stage'] = 'load';
  try {
    const loaded =
      'text' in input ? parseDocumentText(input.text, registry) : loadDocument(input.value, registry);
    if (!loaded.ok) {
      if (loaded.diagnostics.length === 0) problems.push('load: refused without a diagnostic');
      checkDiagnostics('load', loaded.diagnostics, problems);
      return { problems, ms: elapsed(), stage, diagnostics: loaded.diagnostics, beyondGpu };
    }
    // Whatever loads can be saved, shared and kept in the undo history.
    JSON.stringify(loaded.doc);
    structuredClone(loaded.doc);
    stage = 'evaluate';
    const evaluation = evaluateGraph(loaded.doc, registry);
    checkDiagnostics('evaluate', evaluation.diagnostics, problems);
    const { scene } = evaluation;
    for (const bad of nonFiniteNumbers(scene.elements, 'scene.elements')) problems.push(`evaluate: ${bad}`);
    for (const bad of nonFiniteNumbers(scene.tile, 'scene.tile')) problems.push(`evaluate: ${bad}`);
    for (const bad of nonFiniteNumbers(scene.clip, 'scene.clip')) problems.push(`evaluate: ${bad}`);
    for (const bad of nonFiniteNumbers(scene.overlays, 'scene.overlays')) problems.push(`evaluate: ${bad}`);
    for (const bad of nonFiniteNumbers(scene.handles, 'scene.handles')) problems.push(`evaluate: ${bad}`);
    const diagnostics = [...evaluation.diagnostics];
    if (scene.renderNodeId !== null) {
      stage = 'compile';
      for (const baked of [false, true]) {
        const program = compile(scene, { baked });
        checkDiagnostics(`compile${baked ? ' (baked)' : ''}`, program.diagnostics, problems);
        diagnostics.push(...program.diagnostics);
        if (!program.source.startsWith('#version 300 es')) problems.push('compile: source without #version');
        for (const u of program.uniforms) {
          for (const v of u.value) {
            if (!Number.isFinite(v)) problems.push(`compile: uniform ${u.name} holds ${v}`);
            else if (Math.abs(v) > LIMITS.gpuMaxMagnitude) beyondGpu.push(`${u.name} = ${v}`);
          }
        }
        // Finite in float64 but ∞ in the shader: the user must be told (KF405).
        if (beyondGpu.length > 0 && !program.diagnostics.some((d) => d.code === 'KF405'))
          problems.push(`compile: uniforms beyond the GPU's range without KF405: ${beyondGpu.join(', ')}`);
      }
    }
    return { problems, ms: elapsed(), stage, diagnostics, scene, beyondGpu };
  } catch (e) {
    const err = e as Error;
    problems.push(`${stage} threw: ${err?.stack ?? String(e)}`);
    return { problems, ms: elapsed(), stage, diagnostics: [], beyondGpu };
  }
}
