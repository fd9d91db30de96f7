/**
 * Whether pasted text is a whole graph to open (a Kleinflow or Flower document, or a share link)
 * rather than the editor's copied nodes (`kleinflow-clipboard`) or unrelated text.
 */
import { type OpenResult, openDocumentText } from '../../io/document-io.ts';
import { isFlowerDocument } from '../../io/flower/import.ts';
import { formatBytes, INPUT_LIMITS } from '../../io/input-limits.ts';
import { openProblem } from '../../io/open-result.ts';
import { sharePayload } from '../../io/share-url.ts';

function looksLikeDocument(text: string): boolean {
  if (!/\s/.test(text) && sharePayload(text) !== null) return true;
  if (!text.startsWith('{')) return false;
  try {
    const value: unknown = JSON.parse(text);
    if (value === null || typeof value !== 'object') return false;
    return (value as { format?: unknown }).format === 'kleinflow' || isFlowerDocument(value);
  } catch {
    return false;
  }
}

/** The opened document (or its problems) when `text` is meant as one; null when it is not ours. */
export function openPastedText(text: string): OpenResult | null {
  // Past the limit it is not parsed at all; a graph-like start says it was meant as one.
  if (text.length > INPUT_LIMITS.documentBytes) {
    const start = text.trimStart();
    return start.startsWith('{') || sharePayload(start.slice(0, 64)) !== null
      ? openProblem(
          `the pasted text is ${formatBytes(text.length)}, more than ${formatBytes(INPUT_LIMITS.documentBytes)}, the limit for a graph`,
        )
      : null;
  }
  const trimmed = text.trim();
  return looksLikeDocument(trimmed) ? openDocumentText(trimmed) : null;
}
