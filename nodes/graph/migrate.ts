/**
 * Migrations, run once when a document or a pasted fragment enters (load.ts, the clipboard), so
 * that what is in memory is always current and evaluation never migrates:
 * - document migrations by version: DOC_MIGRATIONS[v] turns a version-v document into version
 *   v+1; each works on raw JSON (it runs before validation) and must not throw on odd input;
 * - node migrations: each node type's own (NodeDef.migrations), run by migrateNodes after validation.
 */
import type { NodeDef } from '../core/define-node.ts';
import type { NodeRegistry } from '../core/registry.ts';
import { describeValue } from './describe-value.ts';
import { DOC_VERSION, type GraphNode } from './document.ts';

export type RawDoc = Record<string, unknown>;
export type DocMigration = (doc: RawDoc) => RawDoc;

/** Empty while the format is at version 1; version 2 adds `DOC_MIGRATIONS[1]`. */
export const DOC_MIGRATIONS: Readonly<Record<number, DocMigration>> = {};

export type MigrateResult = { ok: true; doc: RawDoc; from: number } | { ok: false; message: string };

/** Runs every migration from the document's version up to `target`. */
export function migrateDocument(
  doc: RawDoc,
  migrations: Readonly<Record<number, DocMigration>> = DOC_MIGRATIONS,
  target: number = DOC_VERSION,
): MigrateResult {
  const from = doc.version;
  if (typeof from !== 'number' || !Number.isInteger(from) || from < 1) {
    return {
      ok: false,
      message: `version: expected a positive integer, got ${from === undefined ? 'nothing' : describeValue(from)}`,
    };
  }
  if (from > target) {
    return {
      ok: false,
      message: `version: document version ${from} is newer than this Kleinflow understands (${target})`,
    };
  }
  let current = doc;
  for (let v = from; v < target; v++) {
    const step = migrations[v];
    if (!step) return { ok: false, message: `version: no migration from version ${v} to ${v + 1}` };
    current = { ...step(current), version: v + 1 };
  }
  return { ok: true, doc: current, from };
}

const newerThanType = (def: NodeDef, version: number) =>
  `written for version ${version} of "${def.type}", newer than this Kleinflow's (${def.version})`;

export type NodeMigrateResult =
  | { ok: true; params: Record<string, unknown> }
  | { ok: false; message: string };

/**
 * Brings a node's params, written for version `from` of its type (1 when the document does not
 * say), up to `def.version` with the type's own migrations (NodeDef.migrations[v]: v → v+1).
 */
export function migrateNodeParams(
  def: NodeDef,
  params: Record<string, unknown>,
  from = 1,
): NodeMigrateResult {
  if (from > def.version) return { ok: false, message: newerThanType(def, from) };
  let current = params;
  for (let v = from; v < def.version; v++) {
    const step = def.migrations?.[v];
    if (!step) return { ok: false, message: `"${def.type}" has no migration from version ${v} to ${v + 1}` };
    try {
      current = step({ ...current });
    } catch (e) {
      return {
        ok: false,
        message: `migrating "${def.type}" from version ${v} failed: ${(e as Error)?.message}`,
      };
    }
    if (typeof current !== 'object' || current === null || Array.isArray(current)) {
      return {
        ok: false,
        message: `migrating "${def.type}" from version ${v} gave ${describeValue(current)}, not params`,
      };
    }
  }
  return { ok: true, params: current };
}

/** A node's version as stored (1 when the document does not say). */
export const nodeVersion = (node: Pick<GraphNode, 'version'>): number => node.version ?? 1;

/**
 * Every node of a known type brought up to its type's version (params migrated, `version` set),
 * inside groups too.
 * Current nodes and unknown-type placeholders come back as the same objects, so a placeholder
 * round-trips untouched. A node whose migration fails is kept as it was (nothing the user made is
 * lost); evaluation then reports it (KF309, nodeVersionProblem) and does not run it.
 */
export function migrateNodes<N extends GraphNode>(nodes: readonly N[], registry: NodeRegistry): N[] {
  return nodes.map((node) => {
    if (node.group) {
      // A group's nodes are migrated like the document's (docs/architecture.md "Groups").
      const inner = migrateNodes(node.group.nodes, registry);
      const same = inner.every((n, i) => n === node.group!.nodes[i]);
      return same ? node : { ...node, group: { ...node.group, nodes: inner } };
    }
    const def = registry.get(node.type);
    const from = nodeVersion(node);
    if (!def || from === def.version) return node;
    const migrated = migrateNodeParams(def, node.params, from);
    return migrated.ok ? { ...node, version: def.version, params: migrated.params } : node;
  });
}

/**
 * Why a node in memory is not at its type's version (null when it is): it was written by a newer
 * Kleinflow, or its migration on load failed. Decided from the versions alone: evaluation does
 * not migrate.
 */
export function nodeVersionProblem(def: NodeDef, version: number): string | null {
  if (version === def.version) return null;
  if (version > def.version) return newerThanType(def, version);
  for (let v = version; v < def.version; v++) {
    if (!def.migrations?.[v]) return `"${def.type}" has no migration from version ${v} to ${v + 1}`;
  }
  return `written for version ${version} of "${def.type}"; its migration to version ${def.version} failed when it was loaded`;
}
