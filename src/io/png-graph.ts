/**
 * A graph inside a PNG: exported images carry their graph's JSON in an iTXt chunk keyed
 * "kleinflow", so dropping the picture back onto Kleinflow reopens the graph that made it. Every
 * front end (CLI, file drop, paste) reads it through readEmbeddedGraph, so the PNG limits
 * (src/io/input-limits.ts) hold on every path.
 */
import { diag } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { INPUT_LIMITS } from './input-limits.ts';
import { serializeDocument } from './json-text.ts';
import { fromLoad, type OpenResult, openProblem } from './open-result.ts';
import { encodePng, isPng, type PngImage, PngProblem, readPngText, setPngText } from './png.ts';

/** The PNG text keyword that holds the graph. */
export const PNG_GRAPH_KEY = 'kleinflow';

/**
 * PNG bytes with `doc` embedded: `image` is either an encoded PNG (its pixels and other chunks are
 * kept; an older embedded graph is replaced) or raw RGBA pixels to encode.
 */
export function embedGraph(image: Uint8Array | PngImage, doc: GraphDoc): Uint8Array {
  const text = { [PNG_GRAPH_KEY]: serializeDocument(doc) };
  return image instanceof Uint8Array ? setPngText(image, text) : encodePng(image, text);
}

/**
 * The graph text inside PNG bytes, held to Kleinflow's limits: at most INPUT_LIMITS.pngChunks
 * chunks, keywords of at most 79 bytes, the graph at most INPUT_LIMITS.documentBytes (checked
 * before it is decoded). `{ text: undefined }` for a PNG without a graph; `{ problem }` (one line)
 * for a PNG past a limit. Only the graph's own text is decoded.
 */
export function readEmbeddedGraph(bytes: Uint8Array): { text?: string } | { problem: string } {
  try {
    const limits = { chunks: INPUT_LIMITS.pngChunks, textBytes: INPUT_LIMITS.documentBytes };
    return { text: readPngText(bytes, limits, PNG_GRAPH_KEY)?.[PNG_GRAPH_KEY] };
  } catch (e) {
    if (e instanceof PngProblem) return { problem: e.message };
    throw e;
  }
}

/**
 * The embedded graph, loaded and validated, or why there is none: not a PNG, a PNG past a limit
 * (KF504), a PNG without a "kleinflow" entry (a screenshot rather than an exported image), or a
 * damaged graph (with paths).
 */
export function extractGraph(bytes: Uint8Array, registry: NodeRegistry = appRegistry): OpenResult {
  if (!isPng(bytes)) return openProblem('this file is not a PNG image');
  const read = readEmbeddedGraph(bytes);
  if ('problem' in read)
    return { ok: false, diagnostics: [diag('pngRefused', { path: '(file)' }, read.problem)] };
  if (read.text === undefined) {
    return openProblem(
      'this PNG has no Kleinflow graph inside (only images exported by Kleinflow carry one)',
    );
  }
  return fromLoad(parseDocumentText(read.text, registry), 'png');
}
