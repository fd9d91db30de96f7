/**
 * Document migrations by version: DOC_MIGRATIONS[v] turns a version-v document into version v+1.
 * Each migration works on raw JSON (it runs before validation) and must not throw on odd input.
 */
import type { NodeDef } from '../core/define-node.ts';
import { describeValue } from './describe-value.ts';
import { DOC_VERSION } from './document.ts';

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
  if (from > def.version) {
    return {
      ok: false,
      message: `written for version ${from} of "${def.type}", newer than this Kleinflow's (${def.version})`,
    };
  }
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
  }
  return { ok: true, params: current };
}
