/** Downloads and file reading for Save / Open / Export. */

import { diag } from '../../nodes/core/diagnostics.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { type LoadResult, parseDocumentText } from '../../nodes/graph/load.ts';
import { readPngText } from '../io/png.ts';

export function download(name: string, data: BlobPart, type: string): void {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** A file name from the document title: "(2,3,7) tiling" → "2-3-7-tiling". */
export function fileStem(doc: GraphDoc): string {
  const stem = (doc.meta.title ?? 'untitled')
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '');
  return stem || 'untitled';
}

export const documentJson = (doc: GraphDoc): string => `${JSON.stringify(doc, null, 2)}\n`;

/** Reads a .kleinflow.json file, or a PNG exported by Kleinflow (graph in its "kleinflow" text chunk). */
export async function readDocumentFile(file: File): Promise<LoadResult> {
  const bytes = new Uint8Array(await file.arrayBuffer());
  const text = readPngText(bytes);
  if (text) {
    const json = text.kleinflow;
    if (!json) {
      return {
        ok: false,
        diagnostics: [
          diag('importProblem', {}, 'this PNG carries no Kleinflow graph (it was not exported by Kleinflow)'),
        ],
      };
    }
    return parseDocumentText(json);
  }
  return parseDocumentText(new TextDecoder().decode(bytes));
}
