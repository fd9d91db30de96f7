/**
 * Autosave under random editing sessions (fast-check, fixed seed): after every prefix of a
 * session, what the autosaver writes reads back through `restore` — the path the app takes at
 * startup (src/main.tsx) — as the very same document. A saved value that was damaged is reported
 * with its problems and kept (under the backup key, and handed back verbatim), never discarded.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { registry } from '../../../nodes/types/index.ts';
import {
  AUTOSAVE_BACKUP_KEY,
  AUTOSAVE_KEY,
  createAutosaver,
  restore,
  type SaveOutcome,
  type StorageLike,
} from '../../../src/state/autosave.ts';
import { createEditorStore } from '../../../src/state/store.ts';
import { applyEdit, START_DOCS, sessionArb } from './support/edits.ts';

const RUNS = { seed: 42, numRuns: 200 } as const;

/**
 * The document as JSON numbers are: -0 and 0 are one number there (the editor rounds positions,
 * and Math.round(-0.3) is -0). Everything else must come back exactly.
 */
const jsonNumbers = <T>(value: T): T =>
  Object.is(value, -0)
    ? (0 as T)
    : Array.isArray(value)
      ? (value.map(jsonNumbers) as T)
      : value && typeof value === 'object'
        ? (Object.fromEntries(Object.entries(value).map(([k, v]) => [k, jsonNumbers(v)])) as T)
        : value;

class MemoryStorage implements StorageLike {
  readonly data = new Map<string, string>();
  getItem = (k: string) => this.data.get(k) ?? null;
  setItem = (k: string, v: string) => void this.data.set(k, v);
  removeItem = (k: string) => void this.data.delete(k);
}

/** Ways a stored document gets damaged: a write cut short, a hand edit, a newer app's file. */
const damageArb = fc.oneof(
  fc.record({ kind: fc.constant('truncate' as const), at: fc.double({ min: 0, max: 0.999, noNaN: true }) }),
  fc.record({ kind: fc.constant('bad-position' as const), node: fc.nat() }),
  fc.constant({ kind: 'bad-scale' as const }),
  fc.constant({ kind: 'future-version' as const }),
);

type Damage = typeof damageArb extends fc.Arbitrary<infer D> ? D : never;

function damage(text: string, d: Damage): string {
  if (d.kind === 'truncate') return text.slice(0, Math.floor(d.at * text.length));
  const value = JSON.parse(text);
  if (d.kind === 'bad-scale') value.view.scale = -1;
  if (d.kind === 'future-version') value.version = 99;
  if (d.kind === 'bad-position') {
    if (value.nodes.length === 0) value.nodes = 'none';
    else value.nodes[d.node % value.nodes.length].position = 'here';
  }
  return JSON.stringify(value);
}

describe('autosave properties', () => {
  it('after every prefix of a session, the saved document restores to the same document', () => {
    fc.assert(
      fc.property(sessionArb, ({ start, edits }) => {
        const storage = new MemoryStorage();
        const outcomes: SaveOutcome[] = [];
        const saver = createAutosaver(storage, (o) => outcomes.push(o), 400);
        const store = createEditorStore(START_DOCS[start], registry);
        for (const edit of edits) {
          applyEdit(store, edit);
          const { doc } = store.getState();
          saver.schedule(doc);
          saver.flush();
          const restored = restore(storage);
          expect(restored.kind).toBe('ok');
          if (restored.kind === 'ok') expect(restored.doc).toStrictEqual(jsonNumbers(doc));
        }
        saver.dispose();
        expect(outcomes.every((o) => o.ok)).toBe(true);
      }),
      RUNS,
    );
  });

  it('a damaged save is reported with its problems and kept, not discarded', () => {
    fc.assert(
      fc.property(sessionArb, damageArb, ({ start, edits }, how) => {
        const storage = new MemoryStorage();
        const store = createEditorStore(START_DOCS[start], registry);
        for (const edit of edits) applyEdit(store, edit);
        const saver = createAutosaver(storage, () => {}, 400);
        saver.schedule(store.getState().doc);
        saver.flush();
        const broken = damage(storage.getItem(AUTOSAVE_KEY)!, how);
        storage.setItem(AUTOSAVE_KEY, broken);

        const restored = restore(storage);
        expect(restored.kind).toBe('unreadable');
        if (restored.kind !== 'unreadable') return;
        expect(restored.text).toBe(broken);
        expect(restored.problems.length).toBeGreaterThan(0);
        expect(restored.problems.every((p) => p.severity === 'error' && p.message.length > 0)).toBe(true);
        expect(storage.getItem(AUTOSAVE_BACKUP_KEY)).toBe(broken);
        // The app starts on another document and autosaves it: the damaged text survives that.
        saver.schedule(START_DOCS[0]);
        saver.flush();
        expect(storage.getItem(AUTOSAVE_BACKUP_KEY)).toBe(broken);
        saver.dispose();
      }),
      RUNS,
    );
  });
});
