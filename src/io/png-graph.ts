/**
 * A graph inside a PNG: exported images carry their graph's JSON in an iTXt chunk keyed
 * "kleinflow", so dropping the picture back onto Kleinflow reopens the graph that made it.
 */
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';
import { serializeDocument } from './json-text.ts';
import { fromLoad, type OpenResult, openProblem } from './open-result.ts';
import { encodePng, isPng, type PngImage, readPngText, setPngText } from './png.ts';

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
 * The embedded graph, loaded and validated, or why there is none: not a PNG, a PNG without a
 * "kleinflow" entry (a screenshot rather than an exported image), or a damaged graph (with paths).
 */
export function extractGraph(bytes: Uint8Array, registry: NodeRegistry = appRegistry): OpenResult {
  if (!isPng(bytes)) return openProblem('this file is not a PNG image');
  const text = readPngText(bytes)?.[PNG_GRAPH_KEY];
  if (text === undefined) {
    return openProblem(
      'this PNG has no Kleinflow graph inside (only images exported by Kleinflow carry one)',
    );
  }
  return fromLoad(parseDocumentText(text, registry), 'png');
}
