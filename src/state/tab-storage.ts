/**
 * Each browser tab keeps its own document. The autosave used to live only in localStorage, which
 * every tab of the site shares: a share link opened in a second tab saved over the first tab's
 * work, and reloading the first tab then showed the shared graph. Now a tab writes its document to
 * sessionStorage (one per tab, kept across reloads, gone when the tab closes) as well as to
 * localStorage (what a brand-new tab starts from), and reads its own copy first.
 *
 * `tabFirst` wraps the two as one StorageLike so the autosave code (autosave.ts) is unchanged.
 */
import { AUTOSAVE_KEY, type StorageLike } from './autosave.ts';

/** This tab's copy of its document (sessionStorage). */
export const TAB_DOC_KEY = 'kleinflow.tab.doc';
/** Which Recent entry this tab's document is saved as (sessionStorage). */
export const TAB_RECENT_KEY = 'kleinflow.tab.recent';

/**
 * AUTOSAVE_KEY read from the tab's copy when it has one, else the shared one; written to both.
 * Every other key is the shared storage's. `tab` null: no sessionStorage, behave as before.
 */
export function tabFirst(tab: StorageLike | null, shared: StorageLike): StorageLike {
  if (!tab) return shared;
  return {
    getItem(key) {
      if (key !== AUTOSAVE_KEY) return shared.getItem(key);
      return tab.getItem(TAB_DOC_KEY) ?? shared.getItem(key);
    },
    setItem(key, value) {
      if (key !== AUTOSAVE_KEY) return shared.setItem(key, value);
      try {
        tab.setItem(TAB_DOC_KEY, value);
      } catch {
        // The tab's copy would now be older than the shared one: drop it so a reload reads the newer.
        tab.removeItem(TAB_DOC_KEY);
      }
      // A failure here (storage full) is the autosave's to report, as before.
      shared.setItem(key, value);
    },
    removeItem(key) {
      if (key === AUTOSAVE_KEY) tab.removeItem(TAB_DOC_KEY);
      shared.removeItem(key);
    },
  };
}

const session = (): Storage | null => {
  try {
    return window.sessionStorage;
  } catch {
    return null; // storage disabled by policy
  }
};

/** The app's autosave storage: this tab's sessionStorage first, then localStorage. Throws like localStorage does when storage is disabled. */
export const appAutosaveStorage = (): StorageLike => tabFirst(session(), window.localStorage);

/** A new id for a Recent entry (a document as this browser saved it). */
export const newRecentId = (): string =>
  typeof crypto !== 'undefined' && 'randomUUID' in crypto
    ? crypto.randomUUID()
    : `${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`;

/**
 * Which Recent entry this tab saves to: kept across reloads (sessionStorage); a new tab gets a new
 * one, so two tabs never save over each other's entry. In memory only without sessionStorage.
 */
export function tabRecentId(): { get(): string; set(id: string): void } {
  const store = session();
  let id: string | null = null;
  try {
    id = store?.getItem(TAB_RECENT_KEY) ?? null;
  } catch {
    id = null;
  }
  const set = (next: string) => {
    id = next;
    try {
      store?.setItem(TAB_RECENT_KEY, next);
    } catch {
      // full or disabled: the id lives in memory until the tab closes
    }
  };
  if (!id) set(newRecentId());
  return { get: () => id as string, set };
}
