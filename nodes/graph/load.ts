/**
 * Loading a document: JSON text (or an already parsed value) → migrate the document → validate
 * with zod → migrate each node to its type's version. This is the one place documents are
 * migrated: what it returns is current, and evaluation reads params as they are. Problems that
 * make the file unusable come back with their paths and no document; graph-level problems
 * (unknown types, bad edges, cycles) are found later by analyze/evaluate and never stop a load.
 */
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import { LIMITS } from '../core/limits.ts';
import type { NodeRegistry } from '../core/registry.ts';
import { describeValue } from './describe-value.ts';
import { DOC_VERSION, docSchema, FORMAT, type GraphDoc } from './document.ts';
import { pathBeyondDepth } from './json-depth.ts';
import { formatPath } from './json-path.ts';
import { DOC_MIGRATIONS, type DocMigration, migrateDocument, migrateNodes } from './migrate.ts';

export type LoadResult =
  | { ok: true; doc: GraphDoc; migratedFrom: number; diagnostics: Diagnostic[] }
  | { ok: false; diagnostics: Diagnostic[] };

/** At most this many schema problems are listed (a broken file can have thousands). */
const MAX_REPORTED = 50;

export interface LoadOptions {
  /** Document migrations (tests use their own table). */
  readonly migrations?: Readonly<Record<number, DocMigration>>;
  /** The document version to migrate to (DOC_VERSION unless a test says). */
  readonly target?: number;
}

/** `registry` holds the node types whose nodes are migrated (unknown types are kept as they are). */
export function parseDocumentText(text: string, registry: NodeRegistry): LoadResult {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (e) {
    return { ok: false, diagnostics: [diag('notJson', { path: '(document)' }, (e as Error).message)] };
  }
  return loadDocument(value, registry);
}

export function loadDocument(
  value: unknown,
  registry: NodeRegistry,
  { migrations = DOC_MIGRATIONS, target }: LoadOptions = {},
): LoadResult {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) {
    const got = Array.isArray(value) ? 'an array' : value === null ? 'null' : typeof value;
    return {
      ok: false,
      diagnostics: [diag('schema', { path: '(document)' }, `expected a JSON object, got ${got}`)],
    };
  }
  const raw = value as Record<string, unknown>;
  if (raw.format !== FORMAT) {
    return {
      ok: false,
      diagnostics: [
        diag(
          'wrongFormat',
          { path: 'format' },
          raw.format === undefined ? 'missing' : describeValue(raw.format),
        ),
      ],
    };
  }
  const count = countNodes(raw.nodes);
  if (count > LIMITS.maxNodes) {
    return {
      ok: false,
      diagnostics: [diag('tooManyNodes', { path: 'nodes' }, count, LIMITS.maxNodes)],
    };
  }
  const deep = pathBeyondDepth(raw, LIMITS.maxJsonDepth);
  if (deep) {
    const path = formatPath(deep);
    const text = `${path}: nested deeper than ${LIMITS.maxJsonDepth} levels (no Kleinflow document needs that)`;
    return { ok: false, diagnostics: [diag('schema', { path }, text)] };
  }
  // A newer document gets its own code (KF104), so the UI can say "update Kleinflow", not "broken file".
  const newest = target ?? DOC_VERSION;
  if (typeof raw.version === 'number' && Number.isInteger(raw.version) && raw.version > newest) {
    return { ok: false, diagnostics: [diag('futureVersion', { path: 'version' }, raw.version, newest)] };
  }
  let migrated: ReturnType<typeof migrateDocument>;
  try {
    migrated = migrateDocument(raw, migrations, target);
  } catch (e) {
    return {
      ok: false,
      diagnostics: [diag('schema', { path: 'version' }, `migration failed: ${(e as Error).message}`)],
    };
  }
  if (!migrated.ok)
    return { ok: false, diagnostics: [diag('schema', { path: 'version' }, migrated.message)] };
  const parsed = docSchema.safeParse(migrated.doc);
  if (!parsed.success) {
    const diagnostics = parsed.error.issues.slice(0, MAX_REPORTED).map((issue) => {
      const path = formatPath(issue.path);
      return diag('schema', { path }, `${path}: ${issue.message}`);
    });
    if (parsed.error.issues.length > MAX_REPORTED) {
      diagnostics.push(
        diag(
          'schema',
          { path: '(document)' },
          `…and ${parsed.error.issues.length - MAX_REPORTED} more problems`,
        ),
      );
    }
    return { ok: false, diagnostics };
  }
  const doc = { ...parsed.data, nodes: migrateNodes(parsed.data.nodes, registry) };
  return { ok: true, doc, migratedFrom: migrated.from, diagnostics: [] };
}

/**
 * Nodes in raw JSON, those inside groups included (a group must not hide more than the limit),
 * counted before validation; stops as soon as the count passes the limit.
 */
function countNodes(nodes: unknown, depth = 0): number {
  if (!Array.isArray(nodes)) return 0;
  let n = nodes.length;
  if (depth > LIMITS.maxJsonDepth) return n;
  for (const node of nodes) {
    if (n > LIMITS.maxNodes) break;
    const group = (node as { group?: { nodes?: unknown } } | null)?.group;
    if (group && typeof group === 'object') n += countNodes(group.nodes, depth + 1);
  }
  return n;
}
