/**
 * Every examples/*.kleinflow.json, found when the test runs (other work adds examples), loaded and
 * evaluated into its Scene the way the app and the CLI do it.
 */
import { readFileSync } from 'node:fs';
import { hasErrors } from '../../nodes/core/diagnostics.ts';
import type { Scene } from '../../nodes/core/scene.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { examplePath } from '../../src/cli/examples.ts';

export { exampleNames } from '../../src/cli/examples.ts';

export interface LoadedExample {
  /** File name without `.kleinflow.json`. */
  readonly name: string;
  readonly doc: GraphDoc;
  readonly scene: Scene;
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
  const loaded = parseDocumentText(readFileSync(examplePath(name), 'utf8'), registry);
  if (!loaded.ok) throw new Error(`${name}: ${loaded.diagnostics.map((d) => d.message).join('; ')}`);
  return { name, doc: loaded.doc, scene: sceneOf(loaded.doc, name) };
}

/** The document with one point node moved by (dx, dy): what a drag of that point does. */
export function movePoint(doc: GraphDoc, id: string, dx: number, dy: number): GraphDoc {
  return {
    ...doc,
    nodes: doc.nodes.map((n) =>
      n.id === id
        ? { ...n, params: { ...n.params, x: Number(n.params.x) + dx, y: Number(n.params.y) + dy } }
        : n,
    ),
  };
}
