/**
 * What the user is told after opening something: the problems that stopped it (every one, with
 * its JSON path) or the notes of a successful open (a Flower import's unmapped parts, an upgrade).
 */
import type { Diagnostic } from '../../../nodes/core/diagnostics.ts';
import type { OpenResult, OpenSource } from '../../io/document-io.ts';

export interface OpenReport {
  readonly kind: 'error' | 'info';
  /** One line: what was opened and how it went (plain text, shown as text). */
  readonly title: string;
  readonly items: readonly { readonly path: string; readonly text: string; readonly code: string }[];
}

const SOURCE_NAME: Record<OpenSource, string> = {
  kleinflow: 'Kleinflow graph',
  flower: 'Flower graph',
  png: 'graph inside the PNG',
  'share-link': 'shared link',
};

/** One line per problem; a message that already starts with its path does not repeat it. */
function item(d: Diagnostic) {
  const path = d.path ?? '(document)';
  const text = d.message.startsWith(`${path}: `) ? d.message.slice(path.length + 2) : d.message;
  return { path, text, code: d.code };
}

/** The report for `result` from `what` (a file name, "the clipboard", "the link"); null when nothing to say. */
export function openReport(what: string, result: OpenResult): OpenReport | null {
  if (!result.ok) {
    const n = result.diagnostics.length;
    return {
      kind: 'error',
      title: `${what} could not be opened (${n} problem${n === 1 ? '' : 's'}); your graph is unchanged.`,
      items: result.diagnostics.map(item),
    };
  }
  if (result.notes.length === 0) return null;
  return {
    kind: 'info',
    title: `Opened ${what} (${SOURCE_NAME[result.source]}) with ${result.notes.length} note${result.notes.length === 1 ? '' : 's'}:`,
    items: result.notes.map(item),
  };
}
