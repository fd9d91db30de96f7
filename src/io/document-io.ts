/**
 * Save and open, for every front end (editor menus, drag and drop, paste, CLI):
 * - serializeDocument(doc): the text Save writes (canonical key order, 2-space indent, newline);
 * - openDocumentText(text): a Kleinflow document, a Flower graph (recognised by its shape and
 *   imported), or a pasted share link (`…#g=…`);
 * - openBytes(bytes): the same for a dropped file, including a PNG exported by Kleinflow.
 * All return `{ ok: true, doc, notes, source }` or `{ ok: false, diagnostics }`, where every
 * problem carries its JSON path. Loading itself is nodes/graph/load.ts (parse → migrate → validate).
 */
import { diag } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { importFlower, isFlowerDocument } from './flower/import.ts';
import { type OpenResult, openKleinflowValue, openProblem } from './open-result.ts';
import { isPng } from './png.ts';
import { extractGraph } from './png-graph.ts';
import { decodeShareFragment, sharePayload } from './share-url.ts';

export { serializeDocument } from './json-text.ts';
export type { OpenResult, OpenSource } from './open-result.ts';

/** Text that is a share link rather than JSON: one word — `#g=…`, `g=…` or a URL with that fragment. */
const looksLikeShareLink = (text: string) =>
  !text.startsWith('{') && !/\s/.test(text) && sharePayload(text) !== null;

/**
 * Opens JSON text (or a pasted share link). `registry` decides which node types a Flower import
 * may use and which node types' migrations run (default: every registered type).
 */
export function openDocumentText(text: string, registry: NodeRegistry = appRegistry): OpenResult {
  const trimmed = text.replace(/^\uFEFF/, '').trim();
  if (trimmed === '') return openProblem('the file is empty', '(document)');
  if (looksLikeShareLink(trimmed)) {
    const shared = decodeShareFragment(trimmed, registry);
    return shared.ok
      ? { ok: true, doc: shared.doc, notes: [], source: 'share-link' }
      : openProblem(shared.message, '(link)');
  }
  let value: unknown;
  try {
    value = JSON.parse(trimmed);
  } catch (e) {
    return { ok: false, diagnostics: [diag('notJson', { path: '(document)' }, (e as Error).message)] };
  }
  if (isFlowerDocument(value)) {
    const imported = importFlower(value, registry);
    return imported.ok ? { ...imported, source: 'flower' } : imported;
  }
  return openKleinflowValue(value, 'kleinflow', registry);
}

/** Opens a dropped or chosen file: a Kleinflow PNG (its embedded graph) or UTF-8 JSON text. */
export function openBytes(bytes: Uint8Array, registry: NodeRegistry = appRegistry): OpenResult {
  if (isPng(bytes)) return extractGraph(bytes, registry);
  let text: string;
  try {
    text = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    return openProblem('this file is neither a Kleinflow graph (JSON), a Flower graph nor a Kleinflow PNG');
  }
  return openDocumentText(text, registry);
}
