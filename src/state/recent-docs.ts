/**
 * Recent documents: every document this browser autosaved, newest first, with its title, time and
 * a small picture, so a person can reopen work from another tab or an earlier session. Kept in
 * IndexedDB (through idb-keyval) rather than localStorage: documents and PNG thumbnails of many
 * documents would soon fill localStorage's few megabytes, which the autosave itself needs.
 */
import { createStore, del, entries, set, type UseStore } from 'idb-keyval';

/** How many documents are kept; older ones are dropped. */
export const RECENT_LIMIT = 30;

export interface RecentEntry {
  readonly id: string;
  readonly title: string;
  /** When it was saved (ms since 1970). */
  readonly savedAt: number;
  /** A small PNG data URL of the render, when the picture was drawn. */
  readonly thumbnail?: string;
  /** The document as saved (the same JSON as a .kleinflow.json file). */
  readonly text: string;
}

export interface RecentStore {
  /** Saves `entry` (replacing the one with its id) and drops the oldest beyond RECENT_LIMIT. */
  put(entry: RecentEntry): Promise<void>;
  /** Newest first. */
  list(): Promise<RecentEntry[]>;
  /** Forgets the entry with this id (nothing happens when there is none). */
  remove(id: string): Promise<void>;
}

/** The newest `limit` of `all`, and the ids of the rest (to delete). */
export function keepNewest(all: readonly RecentEntry[], limit = RECENT_LIMIT) {
  const sorted = [...all].sort((a, b) => b.savedAt - a.savedAt);
  return { kept: sorted.slice(0, limit), dropped: sorted.slice(limit).map((e) => e.id) };
}

const isEntry = (v: unknown): v is RecentEntry => {
  const e = v as Partial<RecentEntry> | null;
  return typeof e?.id === 'string' && typeof e.text === 'string' && typeof e.savedAt === 'number';
};

/** The browser's store; every call rejects (never throws) when IndexedDB is missing or refused. */
export function idbRecentStore(): RecentStore {
  let db: UseStore | null = null;
  // Opened on first use: createStore itself touches no IndexedDB, but calls through it throw
  // synchronously when `indexedDB` is missing, so each is inside an async function.
  const store = () => {
    db ??= createStore('kleinflow', 'recent');
    return db;
  };
  const list = async () => {
    const all = (await entries(store())).map(([, v]) => v).filter(isEntry);
    return keepNewest(all, Number.POSITIVE_INFINITY).kept;
  };
  return {
    list,
    async put(entry) {
      await set(entry.id, entry, store());
      const { dropped } = keepNewest(await list());
      for (const id of dropped) await del(id, store());
    },
    async remove(id) {
      await del(id, store());
    },
  };
}
