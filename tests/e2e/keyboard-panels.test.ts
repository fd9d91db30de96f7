/**
 * Keyboard paths a newcomer takes to a picture's settings, in Chromium: a drop-down menu answers
 * the arrow keys (↓ on its button opens it at the first item, ↑ ↓ Home End move, Esc hands the
 * focus back to the button); the Inspector opened by Enter takes the keyboard at once (it comes
 * after the whole graph in the tab order), and while no node is selected it offers the render node,
 * whose settings then have the focus; on a phone the Inspector tab's first Tab is that offer, not a
 * port of the graph hidden under it; an example picked in the gallery gives the focus back to the
 * Examples button (the keyboard does not start again at the top of the page).
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import type { ServedApp } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';

let page: Page;
let app: ServedApp;
const problems: string[] = [];
appSessionForSuite((s) => ({ page, app } = s), {
  query: '?test',
  viewport: { width: 1280, height: 720 },
  problems,
  ready: (p) => p.locator('.react-flow__node').first().waitFor(),
});

/** The focused element's accessible text: its aria-label, else its text. */
const focused = () =>
  page.evaluate(() => {
    const a = document.activeElement;
    return a ? (a.getAttribute('aria-label') ?? a.textContent ?? '').trim() : '';
  });

describe('keyboard paths to the settings', () => {
  it('moves through a menu with the arrow keys, and Esc gives the focus back to its button', async () => {
    const exportButton = page.getByRole('button', { name: /^Export/ });
    await exportButton.focus();
    await page.keyboard.press('ArrowDown');
    const items = page.getByRole('menu').getByRole('menuitem');
    await expect.poll(focused).toBe((await items.first().textContent())!.trim());
    await page.keyboard.press('ArrowDown');
    expect(await focused()).toBe((await items.nth(1).textContent())!.trim());
    await page.keyboard.press('ArrowUp');
    await page.keyboard.press('ArrowUp'); // from the first item round to the last
    const enabled = page.getByRole('menu').locator('[role="menuitem"]:not(:disabled)');
    expect(await focused()).toBe((await enabled.last().textContent())!.trim());
    await page.keyboard.press('Home');
    expect(await focused()).toBe((await items.first().textContent())!.trim());
    await page.keyboard.press('Escape');
    await page.getByRole('menu').waitFor({ state: 'detached' });
    expect(await exportButton.evaluate((b) => b === document.activeElement)).toBe(true);
  });

  it('takes the keyboard into the Inspector opened by Enter, and offers the render node', async () => {
    await page.evaluate(() => window.__kleinflow!.store.setSelection([]));
    const toggle = page.getByRole('button', { name: 'Inspector', exact: true });
    await toggle.focus();
    await page.keyboard.press('Enter');
    const inspector = page.getByRole('complementary', { name: 'Inspector' });
    await expect.poll(() => inspector.evaluate((el) => el === document.activeElement)).toBe(true);
    const doc = (await page.evaluate(() => window.__kleinflow!.store.getState().doc)) as GraphDoc;
    const render = doc.nodes.find((n) => n.type === 'render')!;
    const offer = inspector.getByRole('button', { name: /^Inspect / });
    expect(await offer.textContent()).toBe(`Inspect ${render.label ?? 'Render'}`);
    // Within two Tabs (past the panel's Close), then Enter.
    for (let i = 0; i < 2 && !(await offer.evaluate((b) => b === document.activeElement)); i++)
      await page.keyboard.press('Tab');
    expect(await offer.evaluate((b) => b === document.activeElement)).toBe(true);
    await page.keyboard.press('Enter');
    await inspector.getByRole('heading', { name: 'Render' }).waitFor();
    expect(await page.evaluate(() => [...window.__kleinflow!.store.getState().selection])).toEqual([
      render.id,
    ]);
    await expect.poll(() => inspector.evaluate((el) => el === document.activeElement)).toBe(true);
    // The render node's own settings are next in the panel.
    await page.keyboard.press('Tab');
    expect(await inspector.evaluate((el) => el.contains(document.activeElement))).toBe(true);
    expect(problems).toEqual([]);
  });

  it('on a phone the Inspector tab takes Tab to its own controls, not to the graph hidden under it', async () => {
    const context = await app.newContext({ width: 390, height: 844 });
    try {
      const phone = await context.newPage();
      await phone.goto(`${app.url}?test`);
      await phone.waitForFunction(() => window.__kleinflow?.store);
      await phone.evaluate(() => window.__kleinflow!.store.setSelection([]));
      await phone.getByRole('tab', { name: 'Inspector' }).focus();
      await phone.keyboard.press('Enter');
      const inspector = phone.getByRole('complementary', { name: 'Inspector' });
      const offer = inspector.getByRole('button', { name: /^Inspect / });
      await offer.waitFor();
      await phone.keyboard.press('Tab');
      expect(await offer.evaluate((b) => b === document.activeElement)).toBe(true);
      await phone.keyboard.press('Enter');
      await inspector.getByRole('heading', { name: 'Render' }).waitFor();
    } finally {
      await context.close();
    }
  });

  it('gives the focus back to Examples once an example is picked from the gallery', async () => {
    const examples = page.getByRole('button', { name: 'Examples', exact: true });
    await examples.focus();
    await page.keyboard.press('Enter');
    const search = page.getByRole('searchbox', { name: 'Search examples' });
    await expect.poll(() => search.evaluate((el) => el === document.activeElement)).toBe(true);
    await page.keyboard.type('*442');
    await page.keyboard.press('Tab');
    await page.keyboard.press('Enter');
    await page.getByRole('dialog', { name: 'Examples' }).waitFor({ state: 'detached' });
    await expect
      .poll(() => page.evaluate(() => window.__kleinflow!.store.getState().doc.meta.title ?? ''))
      .toMatch(/\*442/);
    await expect.poll(() => examples.evaluate((b) => b === document.activeElement)).toBe(true);
    // Enter in the search box opens the first match: the focus comes back without that Enter
    // clicking Examples and opening the gallery again.
    await page.keyboard.press('Enter');
    await search.waitFor();
    await page.keyboard.type('*333');
    await page.keyboard.press('Enter');
    await page.getByRole('dialog', { name: 'Examples' }).waitFor({ state: 'detached' });
    await expect.poll(() => examples.evaluate((b) => b === document.activeElement)).toBe(true);
    expect(await page.getByRole('dialog', { name: 'Examples' }).count()).toBe(0);
  });
});
