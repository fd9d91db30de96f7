/**
 * Autosave: the document is written to storage (localStorage in the app) a short while after each
 * change and read back on start. A saved document that cannot be read is never thrown away: it is
 * kept under a backup key and offered for download. A full storage is reported, not ignored.
 */
import type { Diagnostic } from '../../nodes/core/diagnostics.ts';
import type { NodeRegistry } from '../../nodes/core/registry.ts';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry as appRegistry } from '../../nodes/types/index.ts';

export const AUTOSAVE_KEY = 'kleinflow.autosave';
export const AUTOSAVE_BACKUP_KEY = 'kleinflow.autosave.unreadable';
export const AUTOSAVE_DELAY_MS = 400;

export type StorageLike = Pick<Storage, 'getItem' | 'setItem' | 'removeItem'>;

export type Restored =
  | { kind: 'none' }
  | { kind: 'ok'; doc: GraphDoc }
  /**
   * `text` is what was stored; `problems` say why it could not be loaded. `backedUp`: a copy is
   * under AUTOSAVE_BACKUP_KEY; when false (storage full) the only copy is still under
   * AUTOSAVE_KEY, and autosave must be held (createAutosaveHold) so that it is not overwritten.
   */
  | { kind: 'unreadable'; text: string; problems: readonly Diagnostic[]; backedUp: boolean };

/** The saved document, migrated to `registry`'s node types like any other document that is opened. */
export function restore(storage: StorageLike, registry: NodeRegistry = appRegistry): Restored {
  let text: string | null;
  try {
    text = storage.getItem(AUTOSAVE_KEY);
  } catch {
    return { kind: 'none' }; // storage disabled (private mode, policy): nothing to restore
  }
  if (text === null) return { kind: 'none' };
  const loaded = parseDocumentText(text, registry);
  if (loaded.ok) return { kind: 'ok', doc: loaded.doc };
  let backedUp = true;
  try {
    // Keep the unreadable text out of the way of the next save, so it is not overwritten.
    storage.setItem(AUTOSAVE_BACKUP_KEY, text);
  } catch {
    // The backup failed (storage full): the text stays under AUTOSAVE_KEY, which autosave must
    // leave alone until the user has downloaded or discarded it.
    backedUp = false;
  }
  return { kind: 'unreadable', text, problems: loaded.diagnostics, backedUp };
}

export type SaveOutcome =
  | { ok: true }
  | { ok: false; reason: 'quota' | 'unavailable' | 'held'; message: string };

/**
 * Autosave paused while an unreadable autosave that could not be backed up is the only copy of
 * the user's last session; released once they downloaded or discarded it.
 */
export interface AutosaveHold {
  readonly held: boolean;
  release(): void;
  /** Calls `fn` once, when released; returns an unsubscribe. */
  onRelease(fn: () => void): () => void;
}

export function createAutosaveHold(held: boolean): AutosaveHold {
  const listeners = new Set<() => void>();
  return {
    get held() {
      return held;
    },
    release() {
      if (!held) return;
      held = false;
      for (const fn of listeners) fn();
      listeners.clear();
    },
    onRelease(fn) {
      listeners.add(fn);
      return () => void listeners.delete(fn);
    },
  };
}

const HELD_MESSAGE =
  'Autosave is paused: your last session could not be restored and there is no room to back it up. Download or discard it to resume.';

export function isQuotaError(e: unknown): boolean {
  const err = e as { name?: string; code?: number } | null;
  return err?.name === 'QuotaExceededError' || err?.name === 'NS_ERROR_DOM_QUOTA_REACHED' || err?.code === 22;
}

export function saveNow(storage: StorageLike, doc: GraphDoc): SaveOutcome {
  try {
    storage.setItem(AUTOSAVE_KEY, JSON.stringify(doc));
    return { ok: true };
  } catch (e) {
    return isQuotaError(e)
      ? {
          ok: false,
          reason: 'quota',
          message: 'Autosave failed: the browser storage is full. Save your graph to a file to keep it.',
        }
      : { ok: false, reason: 'unavailable', message: `Autosave failed: ${(e as Error)?.message ?? e}` };
  }
}

export interface Autosaver {
  /** Schedules a save of `doc` (the last one wins). */
  schedule(doc: GraphDoc): void;
  /** Writes a pending save at once (e.g. before the page unloads). */
  flush(): void;
  dispose(): void;
}

export function createAutosaver(
  storage: StorageLike,
  onOutcome: (outcome: SaveOutcome) => void,
  delayMs = AUTOSAVE_DELAY_MS,
  timers: Pick<typeof globalThis, 'setTimeout' | 'clearTimeout'> = globalThis,
  hold?: AutosaveHold,
): Autosaver {
  let pending: GraphDoc | null = null;
  let timer: ReturnType<typeof setTimeout> | undefined;
  const flush = () => {
    if (timer !== undefined) timers.clearTimeout(timer);
    timer = undefined;
    if (!pending) return;
    if (hold?.held) {
      // Kept pending: written by the first flush after the hold is released.
      onOutcome({ ok: false, reason: 'held', message: HELD_MESSAGE });
      return;
    }
    const doc = pending;
    pending = null;
    onOutcome(saveNow(storage, doc));
  };
  return {
    schedule(doc) {
      pending = doc;
      if (timer !== undefined) timers.clearTimeout(timer);
      timer = timers.setTimeout(flush, delayMs);
    },
    flush,
    dispose() {
      if (timer !== undefined) timers.clearTimeout(timer);
      timer = undefined;
      pending = null;
    },
  };
}
