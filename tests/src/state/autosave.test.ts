import { describe, expect, it } from 'vitest';
import { emptyDocument } from '../../../nodes/graph/document.ts';
import {
  AUTOSAVE_BACKUP_KEY,
  AUTOSAVE_KEY,
  createAutosaveHold,
  createAutosaver,
  restore,
  type SaveOutcome,
  type StorageLike,
} from '../../../src/state/autosave.ts';

class MemoryStorage implements StorageLike {
  data = new Map<string, string>();
  quota = Number.POSITIVE_INFINITY;
  getItem = (k: string) => this.data.get(k) ?? null;
  setItem = (k: string, v: string) => {
    if (v.length > this.quota) {
      const e = new Error('full');
      e.name = 'QuotaExceededError';
      throw e;
    }
    this.data.set(k, v);
  };
  removeItem = (k: string) => void this.data.delete(k);
}

/** Manual timers: run() fires what is due. */
function fakeTimers() {
  let next = 1;
  const due = new Map<number, () => void>();
  return {
    setTimeout: ((fn: () => void) => {
      due.set(next, fn);
      return next++;
    }) as unknown as typeof setTimeout,
    clearTimeout: ((id: number) => due.delete(id)) as unknown as typeof clearTimeout,
    run() {
      const fns = [...due.values()];
      due.clear();
      for (const f of fns) f();
    },
    pending: () => due.size,
  };
}

describe('autosave', () => {
  it('saves debounced (only the last document) and restores it', () => {
    const storage = new MemoryStorage();
    const timers = fakeTimers();
    const outcomes: SaveOutcome[] = [];
    const saver = createAutosaver(storage, (o) => outcomes.push(o), 400, timers);
    saver.schedule(emptyDocument('first'));
    saver.schedule(emptyDocument('second'));
    expect(storage.getItem(AUTOSAVE_KEY)).toBeNull();
    expect(timers.pending()).toBe(1);
    timers.run();
    expect(outcomes).toEqual([{ ok: true }]);
    const restored = restore(storage);
    expect(restored.kind).toBe('ok');
    expect(restored.kind === 'ok' && restored.doc.meta.title).toBe('second');
  });

  it('flush writes at once', () => {
    const storage = new MemoryStorage();
    const saver = createAutosaver(storage, () => {}, 400, fakeTimers());
    saver.schedule(emptyDocument('now'));
    saver.flush();
    expect(storage.getItem(AUTOSAVE_KEY)).toContain('"now"');
  });

  it('nothing stored: nothing restored', () => {
    expect(restore(new MemoryStorage()).kind).toBe('none');
  });

  it('an unreadable save is kept (backup key) and handed back with its problems, not discarded', () => {
    const storage = new MemoryStorage();
    storage.setItem(AUTOSAVE_KEY, '{"format":"kleinflow","version":1,"nodes":[');
    const r = restore(storage);
    expect(r.kind).toBe('unreadable');
    if (r.kind !== 'unreadable') return;
    expect(r.text).toBe('{"format":"kleinflow","version":1,"nodes":[');
    expect(r.problems[0].code).toBe('KF101');
    expect(storage.getItem(AUTOSAVE_BACKUP_KEY)).toBe(r.text);
    expect(r.backedUp).toBe(true);

    storage.setItem(
      AUTOSAVE_KEY,
      JSON.stringify({ ...emptyDocument(), view: { center: [0, 0], scale: -1 } }),
    );
    const bad = restore(storage);
    expect(bad.kind === 'unreadable' && bad.problems[0].message).toMatch(/view\.scale/);
  });

  it('an unreadable save that cannot be backed up is never overwritten until released', () => {
    const storage = new MemoryStorage();
    const broken = `{"format":"kleinflow","nodes":[${'x'.repeat(5_000)}`;
    storage.data.set(AUTOSAVE_KEY, broken); // stored before the storage filled up
    storage.quota = 1_000; // no room for the backup copy
    const r = restore(storage);
    expect(r.kind === 'unreadable' && r.backedUp).toBe(false);
    expect(storage.getItem(AUTOSAVE_BACKUP_KEY)).toBeNull();

    storage.quota = Number.POSITIVE_INFINITY; // an edit's save would fit now: it must still wait
    const hold = createAutosaveHold(true);
    const timers = fakeTimers();
    const outcomes: SaveOutcome[] = [];
    const saver = createAutosaver(storage, (o) => outcomes.push(o), 400, timers, hold);
    saver.schedule(emptyDocument('edited'));
    timers.run();
    saver.flush();
    expect(storage.getItem(AUTOSAVE_KEY)).toBe(broken);
    expect(outcomes[0]).toMatchObject({ ok: false, reason: 'held' });

    // Downloaded or discarded: the next flush writes the pending document.
    hold.release();
    saver.flush();
    expect(storage.getItem(AUTOSAVE_KEY)).toContain('"edited"');
  });

  it('a full storage is reported as such', () => {
    const storage = new MemoryStorage();
    storage.quota = 10;
    const timers = fakeTimers();
    const outcomes: SaveOutcome[] = [];
    createAutosaver(storage, (o) => outcomes.push(o), 400, timers).schedule(emptyDocument());
    timers.run();
    expect(outcomes).toHaveLength(1);
    expect(outcomes[0].ok).toBe(false);
    expect(!outcomes[0].ok && outcomes[0].reason).toBe('quota');
    expect(!outcomes[0].ok && outcomes[0].message).toMatch(/storage is full/);
  });
});
