/**
 * A large corrupt autosave in a full browser storage (Chromium, the built app): the banner must not
 * claim a backup that does not exist, edits must not overwrite the only copy, and after a reload
 * it is still there; "Discard it" resumes autosaving and the banner then says so.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { appSessionForSuite } from './app-suite.ts';

let page: Page;
appSessionForSuite((s) => ({ page } = s), {
  viewport: { width: 1280, height: 720 },
  query: '?test',
  ready: (p) => p.waitForSelector('.react-flow__node'),
});

/** About 4.5 M characters of broken JSON (the rest of the storage is filled up before reload). */
const BROKEN_CHARS = 4_500_000;

const stored = () =>
  page.evaluate(() => {
    const text = localStorage.getItem('kleinflow.autosave');
    return { length: text?.length ?? 0, start: text?.slice(0, 30) ?? '' };
  });

describe('autosave in a full storage', () => {
  it('keeps a corrupt autosave that cannot be backed up, and says so truthfully', async () => {
    // Fill the storage with the broken save (and nothing may write the backup beside it).
    await page.evaluate((n) => {
      localStorage.clear();
      // As a new tab sees it: no copy of its own in sessionStorage (tab-storage.ts), only the shared one.
      sessionStorage.clear();
      localStorage.setItem('kleinflow.autosave', `{"format":"kleinflow","nodes":[${'x'.repeat(n)}`);
      // Then whatever room is left, to within 1 KB.
      let size = 1 << 22;
      for (let i = 0; size >= 1024; ) {
        try {
          localStorage.setItem(`filler${i}`, 'y'.repeat(size));
          i++;
        } catch {
          size >>= 1;
        }
      }
    }, BROKEN_CHARS);
    expect((await stored()).length).toBeGreaterThan(BROKEN_CHARS);
    await page.reload();
    const banner = page.getByRole('alert').filter({ hasText: 'could not be restored' });
    await banner.waitFor();
    const text = await banner.textContent();
    expect(text).not.toMatch(/kept under/);
    expect(text).toMatch(/autosave is paused/);
    expect(await page.evaluate(() => localStorage.getItem('kleinflow.autosave.unreadable'))).toBeNull();
    // The status may show "Saving…" for a moment first (the tab's own copy): wait for the state.
    await expect
      .poll(() => page.getByTestId('save-state').textContent(), { timeout: 20_000 })
      .toMatch(/paused/);

    // An edit, then time for its autosave: the only copy of the broken session is untouched.
    await page.evaluate(() =>
      window.__kleinflow!.store.dispatch({ type: 'set-view', view: { center: [0.1, 0], scale: 3 } }, 'edit'),
    );
    await page.waitForTimeout(1_500);
    expect((await stored()).length).toBeGreaterThan(BROKEN_CHARS);
    await page.reload();
    await page.getByRole('alert').filter({ hasText: 'could not be restored' }).waitFor();
    expect((await stored()).length).toBeGreaterThan(BROKEN_CHARS);

    // Discarding it resumes autosaving: the graph on screen is saved.
    await page.getByRole('button', { name: 'Discard it' }).click();
    await expect.poll(async () => (await stored()).length).toBeLessThan(BROKEN_CHARS);
    expect((await stored()).start).toMatch(/^\{"format":"kleinflow"/);
    await expect.poll(() => page.getByTestId('save-state').textContent()).toMatch(/Saved/);
    // The banner no longer says autosave is paused: it says what happened.
    expect(await page.getByRole('alert').filter({ hasText: 'could not be restored' }).count()).toBe(0);
    await expect
      .poll(() => page.locator('.kf-banners').textContent())
      .toMatch(/Discarded the unreadable session\. Autosave is on again\./);
  }, 120_000);
});
