/** The result shape shared by every "open a graph" path (file, PNG, share link, Flower import). */
import { type Diagnostic, diag } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import { DOC_VERSION, type GraphDoc } from '../../nodes/graph/document.ts';
import { type LoadResult, loadDocument } from '../../nodes/graph/load.ts';

/** Where an opened graph came from, so the UI can say "Imported from Flower" and the like. */
export type OpenSource = 'kleinflow' | 'flower' | 'png' | 'share-link';

export type OpenResult =
  | { ok: true; doc: GraphDoc; notes: Diagnostic[]; source: OpenSource }
  | { ok: false; diagnostics: Diagnostic[] };

/** A load result as an OpenResult; an upgraded document gets an info note saying so. */
export function fromLoad(loaded: LoadResult, source: OpenSource): OpenResult {
  if (!loaded.ok) return loaded;
  const notes = [...loaded.diagnostics];
  if (loaded.migratedFrom < DOC_VERSION) notes.push(diag('migrated', {}, loaded.migratedFrom, DOC_VERSION));
  return { ok: true, doc: loaded.doc, notes, source };
}

/** A parsed JSON value that should be a Kleinflow document (migrated to `registry`'s node types). */
export const openKleinflowValue = (value: unknown, source: OpenSource, registry: NodeRegistry): OpenResult =>
  fromLoad(loadDocument(value, registry), source);

/** A single-problem failure (KF501) with a path such as "(file)". */
export const openProblem = (message: string, path = '(file)'): OpenResult => ({
  ok: false,
  diagnostics: [diag('importProblem', { path }, message)],
});
