/**
 * Canonical JSON text for Kleinflow documents: keys in a fixed order (document fields in schema
 * order, free-form maps such as `params` sorted by name) and a compact-but-readable layout, so
 * saving the same graph twice gives the same bytes and diffs stay small.
 */
import type { GraphDoc } from '../../nodes/graph/document.ts';

/** Preferred key order per object position; keys not listed follow in code-unit order. */
const KEY_ORDER: Readonly<Record<string, readonly string[]>> = {
  document: ['format', 'version', 'meta', 'nodes', 'edges', 'view', 'camera3d'],
  meta: ['title', 'description'],
  node: ['id', 'type', 'version', 'label', 'position', 'params'],
  edge: ['id', 'from', 'to'],
  port: ['node', 'port'],
  view: ['center', 'scale'],
  camera3d: ['position', 'target', 'fovDeg'],
};

/** Which key order applies to the object found under `key` inside an object of order `parent`. */
function childOrder(parent: string | null, key: string | number): string | null {
  if (parent === 'document') {
    if (key === 'meta' || key === 'view' || key === 'camera3d') return key;
    if (key === 'nodes') return 'node-list';
    if (key === 'edges') return 'edge-list';
  }
  if (parent === 'node-list') return 'node';
  if (parent === 'edge-list') return 'edge';
  if (parent === 'edge' && (key === 'from' || key === 'to')) return 'port';
  return null;
}

const byCodeUnit = (a: string, b: string) => (a < b ? -1 : a > b ? 1 : 0);

function orderKeys(obj: Record<string, unknown>, order: readonly string[]): string[] {
  const keys = Object.keys(obj).filter((k) => obj[k] !== undefined);
  const known = order.filter((k) => keys.includes(k));
  const rest = keys.filter((k) => !order.includes(k)).sort(byCodeUnit);
  return [...known, ...rest];
}

/** A copy of `value` whose objects list their keys in canonical order (undefined entries dropped). */
function canonical(value: unknown, order: string | null): unknown {
  if (Array.isArray(value)) return value.map((v, i) => canonical(v, childOrder(order, i)));
  if (value === null || typeof value !== 'object') return value;
  const obj = value as Record<string, unknown>;
  const out: Record<string, unknown> = {};
  for (const k of orderKeys(obj, (order ? KEY_ORDER[order] : undefined) ?? []))
    out[k] = canonical(obj[k], childOrder(order, k));
  return out;
}

/** The document with canonically ordered keys (for compact encodings such as share links). */
export function canonicalDocument(doc: GraphDoc): GraphDoc {
  return canonical(doc, 'document') as GraphDoc;
}

/** Lines are kept at most this wide when a value is written on one line. */
const LINE_WIDTH = 120;

/** A JSON scalar; −0 is written "-0" (valid JSON that parses back to −0; JSON.stringify says "0"). */
const scalar = (v: unknown): string => (Object.is(v, -0) ? '-0' : JSON.stringify(v));

/** One-line JSON; `loose` adds the spaces a person reads easily ("{ "a": 1, "b": [1, 2] }"). */
function oneLine(v: unknown, loose = true): string {
  const comma = loose ? ', ' : ',';
  if (Array.isArray(v)) return `[${v.map((x) => oneLine(x, loose)).join(comma)}]`;
  if (v !== null && typeof v === 'object') {
    const entries = Object.entries(v).map(
      ([k, x]) => `${JSON.stringify(k)}:${loose ? ' ' : ''}${oneLine(x, loose)}`,
    );
    if (entries.length === 0) return '{}';
    return loose ? `{ ${entries.join(comma)} }` : `{${entries.join(comma)}}`;
  }
  return scalar(v);
}

/** Canonical JSON with no whitespace (share links), lossless like serializeDocument. */
export const compactDocumentJson = (doc: GraphDoc): string => oneLine(canonicalDocument(doc), false);

/**
 * Pretty-prints with 2-space indentation; a container is written on one line when it fits in
 * LINE_WIDTH (the document and its node/edge lists always break, one entry per line).
 */
function layout(v: unknown, indent: string, prefixLength: number, depth: number): string {
  const flat = oneLine(v);
  const container = v !== null && typeof v === 'object';
  const isEmpty = container && Object.keys(v as object).length === 0;
  if (!container || isEmpty || (depth >= 2 && indent.length + prefixLength + flat.length <= LINE_WIDTH))
    return flat;
  const inner = `${indent}  `;
  if (Array.isArray(v)) {
    return `[\n${v.map((x) => inner + layout(x, inner, 0, depth + 1)).join(',\n')}\n${indent}]`;
  }
  const entries = Object.entries(v as Record<string, unknown>).map(([k, x]) => {
    const key = `${JSON.stringify(k)}: `;
    return inner + key + layout(x, inner, key.length, depth + 1);
  });
  return `{\n${entries.join(',\n')}\n${indent}}`;
}

/**
 * The text Save writes: canonical key order, 2-space indentation, short values on one line,
 * a trailing newline. serializeDocument(load(serializeDocument(d))) === serializeDocument(d).
 */
export function serializeDocument(doc: GraphDoc): string {
  return `${layout(canonicalDocument(doc), '', 0, 0)}\n`;
}
