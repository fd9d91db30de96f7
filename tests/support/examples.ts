/**
 * Every examples/*.kleinflow.json, found when the test runs (other work adds examples), loaded and
 * evaluated into its Scene the way the app and the CLI do it.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { hasErrors } from '../../nodes/core/diagnostics.ts';
import type { Scene } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';

export const EXAMPLES_DIR = fileURLToPath(new URL('../../examples/', import.meta.url));

export interface LoadedExample {
  /** File name without `.kleinflow.json`. */
  readonly name: string;
  readonly doc: GraphDoc;
  readonly scene: Scene;
}

export function exampleNames(): string[] {
  return readdirSync(EXAMPLES_DIR)
    .filter((f) => f.endsWith('.kleinflow.json'))
    .map((f) => f.slice(0, -'.kleinflow.json'.length))
    .sort();
}

/** Evaluates a document into its Scene; throws when it does not load or has errors. */
export function sceneOf(doc: GraphDoc, label = doc.meta?.title ?? 'document'): Scene {
  const evaluation = evaluateGraph(doc, registry);
  if (hasErrors(evaluation.diagnostics)) {
    throw new Error(`${label}: ${evaluation.diagnostics.map((d) => d.message).join('; ')}`);
  }
  return evaluation.scene;
}

export function loadExample(name: string): LoadedExample {
  const loaded = parseDocumentText(readFileSync(`${EXAMPLES_DIR}${name}.kleinflow.json`, 'utf8'));
  if (!loaded.ok) throw new Error(`${name}: ${loaded.diagnostics.map((d) => d.message).join('; ')}`);
  return { name, doc: loaded.doc, scene: sceneOf(loaded.doc, name) };
}
