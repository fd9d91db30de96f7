/**
 * Framing and popups, as a person meets them: an example opened in a tall render pane is not
 * cropped; Fit (button or F) shows the whole picture; undo after opening an example brings back the
 * previous graph with its view; Escape closes every popup and dialog; every button has a name.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { examplePath } from '../../src/cli/examples.ts';
import { appSessionForSuite } from './app-suite.ts';
import { waitRendered } from './editor-page.ts';

let page: Page;

/** The document's view, read through the test hooks (`?test`). */
const docView = () =>
  page.evaluate(() => {
    const v = window.__kleinflow!.store.getState().doc.view;
    return { center: [...v.center], scale: v.scale };
  });

const paneSize = async () => {
  const b = (await page.getByTestId('render-pane').boundingBox())!;
  return { width: b.width, height: b.height };
};

async function openExample(title: string) {
  await page.getByRole('button', { name: 'Examples' }).click();
  const gallery = page.getByRole('dialog', { name: 'Examples' });
  await gallery.locator('.kf-gallery__card').filter({ hasText: title }).first().click();
  await gallery.waitFor({ state: 'detached' });
  await expect.poll(() => page.getByLabel('Document title').inputValue()).toBe(title);
}

// A render pane much taller than wide (25 % of 1200 px): a square-framed example would be cropped.
appSessionForSuite((s) => ({ page } = s), {
  viewport: { width: 1200, height: 900 },
  query: '?test',
  ready: (p) => p.getByRole('button', { name: 'Help' }).waitFor(),
});

describe('framing', () => {
  it('opens an example in a tall pane zoomed out so its width fits, and undo restores the previous view', async () => {
    await openExample('*333 kaleidoscope: drag the triangle');
    const before = await docView();
    await openExample('(2,3,7) hyperbolic tessellation');
    const pane = await paneSize();
    expect(pane.height).toBeGreaterThan(pane.width * 1.5);
    const view = await docView();
    // The example is saved for a square pane: its scale-wide square must fit the pane's width.
    const saved = JSON.parse(readFileSync(examplePath('hyperbolic-237'), 'utf8')).view.scale as number;
    // (within a pixel of the pane's size: the app measures it a moment earlier than the test)
    expect((view.scale * pane.width) / pane.height).toBeGreaterThanOrEqual(saved * (1 - 2 / pane.width));
    await page.locator('.kf-graph').click({ position: { x: 10, y: 300 } });
    await page.keyboard.press('Control+z');
    await expect.poll(() => page.getByLabel('Document title').inputValue()).toMatch(/333/);
    expect(await docView()).toEqual(before);
    await page.keyboard.press('Control+y');
    await expect.poll(() => page.getByLabel('Document title').inputValue()).toMatch(/2,3,7/);
  });

  it('Fit (button and F) frames the whole clip disk in both dimensions', async () => {
    // Zoom in far, then fit.
    const pane = (await page.getByTestId('render-pane').boundingBox())!;
    await page.mouse.move(pane.x + pane.width / 2, pane.y + pane.height / 2);
    for (let i = 0; i < 5; i++) await page.mouse.wheel(0, -400);
    await expect.poll(async () => (await docView()).scale).toBeLessThan(1);
    await page.getByRole('button', { name: 'Fit', exact: true }).click();
    const { width, height } = await paneSize();
    // The (2,3,7) picture is the unit disk: 2 wide, so the world height is 2 · H/W · 1.08.
    const fitted = 2 * (height / width) * 1.08;
    // (within a pixel or two: the pane's size as the app measured it)
    const relErr = async () => Math.abs((await docView()).scale / fitted - 1);
    await expect.poll(relErr).toBeLessThan(0.005);
    expect((await docView()).center.map((c) => Math.abs(c))).toEqual([0, 0]);
    for (let i = 0; i < 3; i++) await page.mouse.wheel(0, -400);
    await expect.poll(async () => (await docView()).scale).toBeLessThan(fitted / 2);
    await page.locator('.kf-graph').click({ position: { x: 10, y: 300 } });
    await page.keyboard.press('f');
    await expect.poll(relErr).toBeLessThan(0.005);
    await waitRendered(page);
  });
});

describe('popups and names', () => {
  it('Escape closes every popup and dialog', async () => {
    const closes = async (open: () => Promise<void>, popup: ReturnType<Page['locator']>) => {
      await open();
      await popup.waitFor();
      await page.keyboard.press('Escape');
      await popup.waitFor({ state: 'detached' });
    };
    await closes(() => page.getByRole('button', { name: 'Export' }).click(), page.getByRole('menu'));
    await closes(
      () => page.getByRole('button', { name: 'Examples' }).click(),
      page.getByRole('dialog', { name: 'Examples' }),
    );
    await closes(
      () => page.getByRole('button', { name: 'Help' }).click(),
      page.getByRole('dialog', { name: 'Help' }),
    );
    await closes(
      async () => {
        await page.getByRole('button', { name: 'Export' }).click();
        await page.getByRole('menuitem', { name: /PNG/ }).click();
      },
      page.getByRole('dialog', { name: 'Export PNG' }),
    );
    await closes(
      async () => {
        const g = (await page.locator('.kf-graph').boundingBox())!;
        await page.mouse.move(g.x + 40, g.y + g.height - 60);
        await page.keyboard.press('Space');
      },
      page.getByRole('combobox', { name: 'Search node types' }),
    );
  });

  it('a modal dialog keeps the keyboard inside it', async () => {
    await page.getByRole('button', { name: 'Help' }).click();
    const help = page.getByRole('dialog', { name: 'Help' });
    await help.waitFor();
    for (let i = 0; i < 25; i++) {
      await page.keyboard.press('Tab');
      expect(await page.evaluate(() => !!document.activeElement?.closest('dialog[open]'))).toBe(true);
    }
    await page.keyboard.press('Escape');
    await help.waitFor({ state: 'detached' });
  });

  it('every button on screen has an accessible name', async () => {
    const unnamed = await page.evaluate(() =>
      [...document.querySelectorAll('button, [role="button"]')]
        .filter((b) => {
          const el = b as HTMLElement;
          const labelledBy = el.getAttribute('aria-labelledby');
          const name =
            el.getAttribute('aria-label') ||
            (labelledBy && document.getElementById(labelledBy)?.textContent) ||
            el.textContent ||
            el.title;
          return !name?.trim();
        })
        .map((b) => b.outerHTML.slice(0, 120)),
    );
    expect(unnamed).toEqual([]);
  });
});
