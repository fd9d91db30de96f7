/**
 * The one way every CLI command gets a graph: read the file (a .json document, a Flower graph —
 * imported on the fly — or a PNG that Kleinflow exported with its graph embedded), load it
 * (parse → migrate → validate, through src/io/document-io.ts), evaluate it
 * into a Scene, and collect every diagnostic. File problems become one-line CliErrors.
 */

import type { Diagnostic, Severity } from '../../nodes/core/diagnostics.ts';
import { diag, hasErrors } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { Scene } from '../../nodes/core/scene.ts';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { type Evaluation, evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { registry } from '../../nodes/types/index.ts';
import { openDocumentText, serializeDocument } from '../io/document-io.ts';
import { fileLimit, tooLargeMessage } from '../io/input-limits.ts';
import { isPng } from '../io/png.ts';
import { PNG_GRAPH_KEY, readEmbeddedGraph } from '../io/png-graph.ts';
import { CliError, type CliIo } from './command.ts';
import { printable } from './printable.ts';
import { liveFallbackNotes } from './scene-pictures.ts';

/** The iTXt keyword under which exported PNGs carry their graph JSON (its home: src/io/png-graph.ts). */
export { PNG_GRAPH_KEY };

export interface GraphLoad {
  readonly path: string;
  /** The loaded document as text (for embedding into exports): migrated, so it never needs migrating again. */
  readonly text: string;
  /** Absent when the file could not be loaded as a document (see diagnostics). */
  readonly doc?: GraphDoc;
  readonly evaluation?: Evaluation;
  /** Load problems, or every diagnostic of the evaluation. */
  readonly diagnostics: readonly Diagnostic[];
}

const FILE_ERRORS: Readonly<Record<string, string>> = {
  ENOENT: 'no such file',
  EISDIR: 'it is a directory',
  EACCES: 'permission denied',
  EPERM: 'permission denied',
  ENOTDIR: 'a folder on the path is a file',
  EMFILE: 'too many open files',
};

/** One readable line for a failed read or write of `path`. */
export function fileErrorMessage(verb: 'read' | 'write', path: string, error: unknown): string {
  const code = (error as { code?: string } | null)?.code;
  const why = (code && FILE_ERRORS[code]) ?? (error instanceof Error ? error.message : String(error));
  return `cannot ${verb} "${path}": ${why}`;
}

/**
 * Reads a whole graph file (JSON, Flower or PNG), refusing it as soon as it passes its limit
 * (src/io/input-limits.ts): a file whose size says so before reading, an endless one such as
 * /dev/zero after reading just past the limit.
 */
export async function readInput(io: CliIo, path: string): Promise<Uint8Array> {
  const parts: Uint8Array[] = [];
  let total = 0;
  let limit: ReturnType<typeof fileLimit> | undefined;
  try {
    const file = await io.open(path);
    for await (const piece of file.chunks) {
      parts.push(piece);
      total += piece.length;
      // The limit depends on the kind of file, known from its first 8 bytes.
      limit ??= total >= 8 ? fileLimit(concat(parts, total)) : undefined;
      if (!limit) continue;
      if (file.size !== null && file.size > limit.bytes)
        throw new CliError(`cannot read "${path}": ${tooLargeMessage(limit, file.size)}`);
      if (total > limit.bytes) throw new CliError(`cannot read "${path}": ${tooLargeMessage(limit)}`);
    }
  } catch (e) {
    throw e instanceof CliError ? e : new CliError(fileErrorMessage('read', path, e));
  }
  return concat(parts, total);
}

function concat(parts: readonly Uint8Array[], total: number): Uint8Array {
  if (parts.length === 1) return parts[0];
  const out = new Uint8Array(total);
  let at = 0;
  for (const p of parts) {
    out.set(p, at);
    at += p.length;
  }
  return out;
}

/** The document text inside the bytes: UTF-8 JSON, or the graph embedded in a Kleinflow PNG. */
export function documentText(path: string, bytes: Uint8Array): string {
  if (isPng(bytes)) {
    const read = readEmbeddedGraph(bytes);
    if ('problem' in read) {
      const refused = diag('pngRefused', { path: '(file)' }, read.problem);
      throw new CliError(`"${path}": ${formatDiagnostic(refused)}`);
    }
    if (read.text === undefined) throw new CliError(`"${path}" is a PNG without an embedded Kleinflow graph`);
    return read.text;
  }
  try {
    return new TextDecoder('utf-8', { fatal: true, ignoreBOM: false }).decode(bytes);
  } catch {
    throw new CliError(`"${path}" is not UTF-8 text: expected a Kleinflow JSON document or PNG`);
  }
}

/** `types` decides which node types load and migrate (tests use their own; default: every registered type). */
export async function loadGraph(io: CliIo, path: string, types: NodeRegistry = registry): Promise<GraphLoad> {
  const read = documentText(path, await readInput(io, path));
  // A Kleinflow document, or a Flower graph imported on the fly (its notes come first).
  const opened = openDocumentText(read, types);
  if (!opened.ok) return { path, text: read, diagnostics: opened.diagnostics };
  // Exports embed the loaded (migrated) Kleinflow document — never an older version's text, nor
  // the Flower text it came from — as the editor's own PNG export does.
  const text = serializeDocument(opened.doc);
  const evaluation = evaluateGraph(opened.doc, types);
  return {
    path,
    text,
    doc: opened.doc,
    evaluation,
    diagnostics: [...opened.notes, ...evaluation.diagnostics],
  };
}

/**
 * One line per diagnostic: `error KF203 nodes[2].type (node "k"): unknown node type "foo"`.
 * Where the diagnostic has no path, the node's place in the document stands in for it.
 */
export function formatDiagnostic(
  d: Diagnostic,
  doc?: GraphDoc,
  origin?: ReadonlyMap<string, readonly string[]>,
): string {
  const index = d.nodeId === undefined || !doc ? -1 : doc.nodes.findIndex((n) => n.id === d.nodeId);
  const where = d.path ?? (index >= 0 ? `nodes[${index}]` : '');
  const who: string[] = [];
  if (d.nodeId !== undefined) who.push(nodeInGroups(d.nodeId, origin));
  if (d.port !== undefined && !d.path) who.push(`port "${d.port}"`);
  const location = [where, who.length ? `(${who.join(', ')})` : ''].filter(Boolean).join(' ') || '(document)';
  // Schema messages already start with their path; do not say it twice.
  const message =
    d.path && d.message.startsWith(`${d.path}: `) ? d.message.slice(d.path.length + 2) : d.message;
  return printable(`${d.severity} ${d.code} ${location}: ${message}`);
}

/**
 * `node "c"`, or for a node that came out of a group `node "c" in group "g"` (nested groups from the
 * outside in: `in group "g" › "h"`), named by its ids in the document, not the flattened graph's.
 */
function nodeInGroups(flatId: string, origin?: ReadonlyMap<string, readonly string[]>): string {
  const path = origin?.get(flatId);
  if (!path || path.length < 2) return `node "${flatId}"`;
  const groups = path.slice(0, -1).map((id) => `"${id}"`);
  return `node "${path.at(-1)}" in group ${groups.join(' › ')}`;
}

export const countBySeverity = (ds: readonly Diagnostic[]): Record<Severity, number> => ({
  error: ds.filter((d) => d.severity === 'error').length,
  warning: ds.filter((d) => d.severity === 'warning').length,
  info: ds.filter((d) => d.severity === 'info').length,
});

/**
 * Loads the graph, prints its warnings to stderr, and throws when anything is an error (after
 * printing every error), so a broken graph never produces a half-right output.
 */
async function loadChecked(io: CliIo, path: string): Promise<GraphLoad & { evaluation: Evaluation }> {
  const load = await loadGraph(io, path);
  // Live sources are notes worth printing, though info: the picture is not what the browser shows.
  const live = load.evaluation && !load.evaluation.scene3d ? liveFallbackNotes(load.evaluation.scene) : [];
  for (const d of [...load.diagnostics.filter((d) => d.severity !== 'info'), ...live]) {
    io.stderr.write(`${printable(path)}: ${formatDiagnostic(d, load.doc, load.evaluation?.origin)}\n`);
  }
  if (!load.evaluation || hasErrors(load.diagnostics)) {
    const n = countBySeverity(load.diagnostics).error;
    throw new CliError(`"${path}" has ${n} error${n === 1 ? '' : 's'}; nothing was produced`);
  }
  return { ...load, evaluation: load.evaluation };
}

const noRender = (path: string) =>
  new CliError(`"${path}" has no render node: add one and wire elements into it`);

/** For commands that need a picture of the plane (render, sample, glsl): see loadChecked. */
export async function loadScene(io: CliIo, path: string): Promise<GraphLoad & { scene: Scene }> {
  const load = await loadChecked(io, path);
  if (load.evaluation.scene3d)
    throw new CliError(
      `"${path}" is a 3D graph (its render node is Render 3D): this command works on 2D graphs`,
    );
  if (load.evaluation.scene.renderNodeId === null) throw noRender(path);
  return { ...load, scene: load.evaluation.scene };
}

/** A graph's picture, of the plane or of space (a render-3d node). */
export type AnyScene =
  | { readonly kind: '2d'; readonly scene: Scene }
  | { readonly kind: '3d'; readonly scene3d: Scene3d };

/** For commands that work on 2D and 3D graphs alike (sample): see loadChecked. */
export async function loadAnyScene(
  io: CliIo,
  path: string,
): Promise<GraphLoad & { evaluation: Evaluation; picture: AnyScene }> {
  const load = await loadChecked(io, path);
  const { scene, scene3d } = load.evaluation;
  if (scene3d) return { ...load, picture: { kind: '3d', scene3d } };
  if (scene.renderNodeId === null) throw noRender(path);
  return { ...load, picture: { kind: '2d', scene } };
}
