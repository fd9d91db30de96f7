/**
 * An automated WCAG 2.1 A/AA audit (axe-core) of what a class sees: the editor with an example,
 * the examples gallery, Help, the mesh export dialog, Present, the 3D view with its handles (Fig. 37)
 * and the Fig. 6 limit-set overlay, and the phone layout (390×844). No serious or critical
 * violation may remain. axe's own source is injected into the page, so it audits the real DOM
 * with the browser's computed styles (contrast needs those).
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { repoRoot, type ServedApp, serveApp } from './app-server.ts';
import { audit, readable } from './axe-audit.ts';
import { waitRendered } from './editor-page.ts';
import { menu, openExampleFile, openViaPicker } from './io-page.ts';

const shots = join(repoRoot, 'test-artifacts');

/** Audits, runs `after` (closing a dialog, so the next case starts clean), then asserts. */
async function expectClean(page: Page, after?: () => Promise<void>) {
  const text = readable(await audit(page));
  await after?.();
  expect(text, text).toBe('');
}

const openExample = async (page: Page, app: ServedApp) => {
  await page.goto(app.url);
  await page.locator('.react-flow__node').first().waitFor();
};

describe('accessibility audit (axe-core, WCAG 2.1 A/AA)', () => {
  let app: ServedApp;
  let page: Page;
  beforeAll(async () => {
    mkdirSync(shots, { recursive: true });
    app = await serveApp();
    page = await (await app.newContext({ width: 1280, height: 720 })).newPage();
    await openExample(page, app);
  });
  afterAll(() => app?.close());

  it('the editor with an example', async () => {
    await expectClean(page);
    // The focus ring on a port, as a keyboard user sees it (Tab, so it is :focus-visible).
    await page.locator('.react-flow__handle.kf-port').first().focus();
    await page.keyboard.press('Shift+Tab');
    await page.keyboard.press('Tab');
    await page.screenshot({ path: join(shots, 'a11y-editor-1280.png') });
  }, 60_000);

  it('the examples gallery', async () => {
    await page.getByRole('button', { name: 'Examples' }).click();
    const gallery = page.getByRole('dialog', { name: 'Examples' });
    await gallery.waitFor();
    await expectClean(page, async () => {
      await page.keyboard.press('Escape');
      await gallery.waitFor({ state: 'detached' });
    });
  }, 60_000);

  it('Help', async () => {
    await page.getByRole('button', { name: 'Help' }).click();
    const help = page.getByRole('dialog', { name: 'Help' });
    await help.waitFor();
    // The keys for building without a pointer are documented where a pupil looks for them.
    expect(await help.getByRole('table', { name: 'Keyboard only' }).textContent()).toMatch(/Enter on a port/);
    await expectClean(page, async () => {
      await page.keyboard.press('Escape');
      await help.waitFor({ state: 'detached' });
    });
  }, 60_000);

  it('the mesh export dialog, with its format choice', async () => {
    await menu(page, 'Export', 'Mesh \\(3D print');
    const dialog = page.getByRole('dialog', { name: 'Export mesh' });
    await dialog.waitFor();
    await dialog.getByLabel('Format').selectOption('3mf');
    await expectClean(page, async () => {
      await page.keyboard.press('Escape');
      await dialog.waitFor({ state: 'detached' });
    });
  }, 60_000);

  it('Present', async () => {
    await page.getByRole('button', { name: 'Present' }).click();
    await page.getByTestId('present-mode').waitFor();
    await expectClean(page);
  }, 60_000);

  it('the 3D view: its keyboard-movable handles (Fig. 37) and the limit-set overlay (Fig. 6)', async () => {
    const p3 = await (await app.newContext({ width: 1280, height: 720 })).newPage();
    p3.setDefaultTimeout(120_000);
    await openExample(p3, app);
    await openExampleFile(p3, 'fig37-indras-bubbles-mirror', '3d', 120_000);
    await p3.locator('[data-handle]').first().waitFor();
    await expectClean(p3);
    await openExampleFile(p3, 'fig06-quaternion-kleinian-group', '3d', 120_000);
    await p3.locator('[data-testid="limit-set-overlay"][data-search]').waitFor();
    await expectClean(p3);
    await p3.context().close();
  }, 300_000);

  it('the phone layout (390×844): picture, graph and menu', async () => {
    const phone = await (await app.newContext({ width: 390, height: 844 })).newPage();
    // A phone opens on the Picture tab; the graph is one tap away.
    await phone.goto(app.url);
    await phone.getByRole('tab', { name: 'Graph' }).waitFor();
    await expectClean(phone);
    await phone.getByRole('tab', { name: 'Graph' }).click();
    await phone.locator('.react-flow__node').first().waitFor();
    await expectClean(phone);
    await phone.screenshot({ path: join(shots, 'a11y-phone-graph.png') });
    await phone.getByRole('button', { name: 'Menu' }).click();
    await phone.getByRole('menu').waitFor();
    await expectClean(phone);
  }, 120_000);

  it('prefers-reduced-motion: an animated example opens paused and stays still until Play', async () => {
    const still = await (await app.newContext({ width: 1280, height: 720 })).newPage();
    await still.emulateMedia({ reducedMotion: 'reduce' });
    await still.goto(`${app.url}?test`);
    const example = join(repoRoot, 'examples', 'animated-breathing-loxodromic.kleinflow.json');
    await openViaPicker(still, 'animated.kleinflow.json', readFileSync(example));
    await waitRendered(still);
    const clock = () =>
      still.evaluate(() => {
        const s = window.__kleinflow!.store.getState();
        return { playing: s.playing, time: s.time };
      });
    expect(await clock()).toEqual({ playing: false, time: 0 });
    // Nothing starts later either: the picture is done and the clock has not moved.
    await still
      .getByTestId('render-progress')
      .filter({ hasText: /^Rendered/ })
      .waitFor();
    expect(await clock()).toEqual({ playing: false, time: 0 });
    // No transitions: a port's hover growth happens at once.
    const transition = await still
      .locator('.react-flow__handle.kf-port')
      .first()
      .evaluate((el) => getComputedStyle(el).transitionDuration);
    expect(transition.split(',').every((d) => Number.parseFloat(d) === 0)).toBe(true);
    // The reader's own Play still plays.
    await still.getByRole('button', { name: 'Play animation' }).focus();
    await still.keyboard.press('Enter');
    await expect.poll(async () => (await clock()).time, { timeout: 20_000 }).toBeGreaterThan(0);
  }, 180_000);
});
