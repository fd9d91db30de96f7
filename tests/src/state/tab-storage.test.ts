import { describe, expect, it } from 'vitest';
import { AUTOSAVE_KEY, type StorageLike } from '../../../src/state/autosave.ts';
import { keepNewest, type RecentEntry } from '../../../src/state/recent-docs.ts';
import { TAB_DOC_KEY, tabFirst } from '../../../src/state/tab-storage.ts';

const memory = (full = false): StorageLike & { data: Map<string, string> } => {
  const data = new Map<string, string>();
  return {
    data,
    getItem: (k) => data.get(k) ?? null,
    setItem: (k, v) => {
      if (full) throw new DOMException('full', 'QuotaExceededError');
      data.set(k, v);
    },
    removeItem: (k) => void data.delete(k),
  };
};

describe('each tab keeps its own autosave', () => {
  it('reads the tab’s copy first, else the shared one; writes both', () => {
    const tab = memory();
    const shared = memory();
    shared.setItem(AUTOSAVE_KEY, 'other tab');
    const s = tabFirst(tab, shared);
    expect(s.getItem(AUTOSAVE_KEY)).toBe('other tab');
    s.setItem(AUTOSAVE_KEY, 'mine');
    shared.setItem(AUTOSAVE_KEY, 'other tab again'); // another tab saves later
    expect(s.getItem(AUTOSAVE_KEY)).toBe('mine');
    expect(tab.data.get(TAB_DOC_KEY)).toBe('mine');
  });

  it('a full shared storage is still reported; a full tab storage drops its stale copy', () => {
    const sharedFull = tabFirst(memory(), memory(true));
    expect(() => sharedFull.setItem(AUTOSAVE_KEY, 'x')).toThrow('full');
    const tab = memory();
    tab.setItem(TAB_DOC_KEY, 'old');
    const full = memory(true);
    const shared = memory();
    const s = tabFirst({ ...full, removeItem: tab.removeItem, getItem: tab.getItem }, shared);
    s.setItem(AUTOSAVE_KEY, 'new');
    expect(s.getItem(AUTOSAVE_KEY)).toBe('new');
  });
});

describe('the Recent list', () => {
  it('keeps the newest entries, newest first', () => {
    const entries: RecentEntry[] = [3, 1, 4, 2].map((t) => ({
      id: `d${t}`,
      title: '',
      savedAt: t,
      text: '{}',
    }));
    const { kept, dropped } = keepNewest(entries, 2);
    expect(kept.map((e) => e.id)).toEqual(['d4', 'd3']);
    expect(dropped.sort()).toEqual(['d1', 'd2']);
  });
});
