/**
 * Downloads and file reading for Save / Open / Export. Every format decision lives in src/io
 * (document-io.ts): this file only moves bytes between the browser and those functions.
 */
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { type OpenResult, openBytes, serializeDocument } from '../io/document-io.ts';
import { fileLimit, tooLargeMessage } from '../io/input-limits.ts';
import { openProblem } from '../io/open-result.ts';

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

/** Save: downloads `<title>.kleinflow.json` with the canonical text of serializeDocument. */
export function saveDocument(doc: GraphDoc): void {
  download(`${fileStem(doc)}.kleinflow.json`, serializeDocument(doc), 'application/json');
}

/**
 * Reads a chosen or dropped file: Kleinflow JSON, a Flower graph or a Kleinflow PNG. A file past
 * its limit (src/io/input-limits.ts) is refused from its size, before anything is read.
 */
export async function readDocumentFile(file: File): Promise<OpenResult> {
  try {
    const limit = fileLimit(new Uint8Array(await file.slice(0, 8).arrayBuffer()));
    if (file.size > limit.bytes) return openProblem(tooLargeMessage(limit, file.size));
    return openBytes(new Uint8Array(await file.arrayBuffer()));
  } catch (e) {
    // A file the browser cannot read, or a reader bug: the user is told, the page keeps working.
    return openProblem(`the file could not be read: ${e instanceof Error ? e.message : String(e)}`);
  }
}
