/**
 * Two tabs of one browser (one context, so they share localStorage and IndexedDB, as real tabs do):
 * a share link opened in the second must not cost the first its work. Tab 1 builds a small graph,
 * tab 2 opens a `#g=` link, tab 1 reloads and still has its graph; Recent lists both documents, with
 * a thumbnail, reopens them by keyboard, and removes one (undoably). Without IndexedDB the work is still autosaved, and the
 * person is told once.
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { BrowserContext, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { examplePath } from '../../src/cli/examples.ts';
import { encodeShareFragment } from '../../src/io/share-url.ts';
import { repoRoot, type ServedApp, serveApp } from './app-server.ts';
import { addNode, nodeCount, waitRendered } from './editor-page.ts';

let app: ServedApp;
let context: BrowserContext;

const SHARED = parseDocumentText(readFileSync(examplePath('fig02-four-kissing-disks'), 'utf8'), registry);
if (!SHARED.ok) throw new Error('example unreadable');
const sharedDoc = SHARED.doc;
const sharedTitle = sharedDoc.meta.title!;
const fragment = encodeShareFragment(sharedDoc);
if (!fragment.ok) throw new Error(fragment.message);
const MINE = 'Tab one construction';

beforeAll(async () => {
  app = await serveApp();
  context = await app.newContext({ width: 1280, height: 720 });
  mkdirSync(join(repoRoot, 'test-artifacts'), { recursive: true });
}, 180_000);

afterAll(async () => {
  await app?.close();
});

const title = (page: Page) => page.getByLabel('Document title').inputValue();
const saved = (page: Page) =>
  page.getByTestId('save-state').filter({ hasText: 'Saved' }).waitFor({ timeout: 30_000 });

/** What Recent lists now, "title: picture" each (opens the dialog, reads, closes it with Escape). */
async function recentEntries(page: Page): Promise<string[]> {
  await page.getByRole('button', { name: 'Recent', exact: true }).click();
  const list = page.getByRole('list', { name: 'Recent documents' });
  await list.waitFor({ timeout: 30_000 });
  const entries = await list.locator('.kf-gallery__card').evaluateAll((buttons) =>
    buttons.map((b) => {
      const src = b.querySelector('img')?.getAttribute('src') ?? '';
      return `${b.querySelector('strong')?.textContent}: ${src.startsWith('data:image/png;base64,') ? 'png' : 'none'}`;
    }),
  );
  await page.keyboard.press('Escape');
  // Gone from the page, not just closed (a closed dialog's list is hidden, which role queries skip).
  await page.locator('dialog[aria-labelledby="kf-recent-title"]').waitFor({ state: 'detached' });
  return entries;
}

describe('two tabs', () => {
  it('a share link opened in tab 2 leaves tab 1 its work; Recent lists and reopens both', async () => {
    const one = await context.newPage();
    await one.goto(app.url);
    await expect.poll(() => nodeCount(one), { timeout: 30_000 }).toBeGreaterThan(0);
    await one.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => nodeCount(one)).toBe(0);
    await one.getByLabel('Document title').fill(MINE);
    await one.getByLabel('Document title').press('Enter');
    await addNode(one, 'point', 60, 60);
    await addNode(one, 'circle', 360, 60);
    await saved(one);

    const two = await context.newPage();
    await two.goto(`${app.url}${fragment.fragment}`);
    await expect.poll(() => title(two), { timeout: 30_000 }).toBe(sharedTitle);
    await saved(two);
    // Its Recent entry gets the picture once drawn.
    await waitRendered(two);

    await one.reload();
    await expect.poll(() => title(one), { timeout: 30_000 }).toBe(MINE);
    expect(await nodeCount(one)).toBe(2);
    // And tab 2 keeps the shared graph across its own reload.
    await two.reload();
    await expect.poll(() => title(two), { timeout: 30_000 }).toBe(sharedTitle);

    // Recent (written a moment after each change) lists both, the shared one with its picture.
    await expect
      .poll(() => recentEntries(one), { timeout: 90_000, interval: 1000 })
      .toEqual(expect.arrayContaining([expect.stringMatching(MINE), `${sharedTitle}: png`]));
    // Keyboard: the Recent button opens the list, Tab reaches the entries, Enter reopens one.
    await one.getByRole('button', { name: 'Recent', exact: true }).press('Enter');
    const list = one.getByRole('list', { name: 'Recent documents' });
    const shared = list.getByRole('button', { name: new RegExp(`^${sharedTitle}`) });
    await list.waitFor({ timeout: 30_000 });
    await one.screenshot({ path: join(repoRoot, 'test-artifacts', 'recent-1280.png') });
    await shared.waitFor();
    // From the dialog's close button, Tab goes down the list: press it until the shared one is focused.
    for (let i = 0; i < 16 && !(await shared.evaluate((b) => b === document.activeElement)); i++)
      await one.keyboard.press('Tab');
    expect(await shared.evaluate((b) => b === document.activeElement)).toBe(true);
    await one.keyboard.press('Enter');
    await list.waitFor({ state: 'detached' });
    await expect.poll(() => title(one)).toBe(sharedTitle);
    await expect.poll(() => nodeCount(one)).toBe(sharedDoc.nodes.length);
    // Tab 1's own construction is still there to go back to.
    await one.getByRole('button', { name: 'Recent', exact: true }).click();
    await list.getByRole('button', { name: new RegExp(`^${MINE}`) }).click();
    await expect.poll(() => title(one)).toBe(MINE);
    expect(await nodeCount(one)).toBe(2);
    // Remove: the entry this tab edits has no Remove button (it would come back at the next
    // change); the shared one goes, and Undo puts it back.
    await one.getByRole('button', { name: 'Recent', exact: true }).click();
    await list.waitFor({ timeout: 30_000 });
    expect(await list.getByRole('button', { name: `Remove “${MINE}” from Recent` }).count()).toBe(0);
    await list.getByRole('button', { name: `Remove “${sharedTitle}” from Recent` }).click();
    await shared.waitFor({ state: 'detached', timeout: 30_000 });
    await one
      .getByRole('status')
      .filter({ hasText: `Removed “${sharedTitle}”` })
      .waitFor();
    await one.getByRole('button', { name: `Undo removing “${sharedTitle}”` }).click();
    await shared.waitFor({ timeout: 30_000 });
    await one.keyboard.press('Escape');
    await one.close();
    await two.close();
  }, 180_000);

  it('without IndexedDB the work is still autosaved, and Recent says why it is empty, once', async () => {
    const page = await context.newPage();
    await page.addInitScript(() => Object.defineProperty(window, 'indexedDB', { value: undefined }));
    await page.goto(app.url);
    await expect.poll(() => nodeCount(page), { timeout: 30_000 }).toBeGreaterThan(0);
    await page.getByRole('button', { name: 'New' }).click();
    await addNode(page, 'point', 60, 60);
    const banner = page.getByRole('status').filter({ hasText: 'Recent documents cannot be kept' });
    await banner.waitFor({ timeout: 30_000 });
    await addNode(page, 'point', 360, 60);
    await saved(page);
    expect(await banner.count()).toBe(1);
    await page.reload();
    await expect.poll(() => nodeCount(page), { timeout: 30_000 }).toBe(2);
    await page.close();
  }, 120_000);

  it('on a phone, Recent is in the ☰ menu and its list fits the width', async () => {
    const phone = await app.newContext({ width: 390, height: 844 });
    const page = await phone.newPage();
    await page.goto(app.url);
    await page.getByRole('button', { name: 'Menu' }).click();
    await page.getByRole('menuitem', { name: /^Recent/ }).click();
    const dialog = page.getByRole('dialog', { name: 'Recent' });
    await dialog.waitFor({ timeout: 30_000 });
    await page
      .getByRole('status')
      .filter({ hasText: /Nothing saved yet|Recent documents/ })
      .waitFor();
    const box = (await dialog.boundingBox())!;
    expect(box.x).toBeGreaterThanOrEqual(0);
    expect(box.x + box.width).toBeLessThanOrEqual(390);
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'recent-390.png') });
    await phone.close();
  }, 120_000);
});
