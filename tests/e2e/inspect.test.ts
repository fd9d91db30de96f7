/**
 * "Explain this pixel" as a person uses it: Inspect in the toolbar, a click on the (2,3,7) picture
 * opens the panel — the word of mirrors applied is as long as the depth shown, the GPU's depth at
 * that pixel is read back and agrees, the orbit is drawn as numbered steps; Escape closes the
 * panel, then leaves inspect mode; Alt-click inspects without the toggle, and in inspect mode a
 * click on a construction handle inspects instead of dragging it. Saves the README screenshot.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { appSessionForSuite } from './app-suite.ts';
import { waitRendered } from './editor-page.ts';

let page: Page;

const SCREENSHOT = 'examples/screenshots/inspect.png';

async function openExample(title: string) {
  await page.getByRole('button', { name: 'Examples' }).click();
  const gallery = page.getByRole('dialog', { name: 'Examples' });
  await gallery.locator('.kf-gallery__card').filter({ hasText: title }).first().click();
  await gallery.waitFor({ state: 'detached' });
  await page.waitForFunction((t) => window.__kleinflow?.store.getState().doc.meta.title === t, title);
  await waitRendered(page);
}

/** Clicks the render pane at a fraction of its size (0.5, 0.5: the middle). */
async function clickPicture(fx: number, fy: number, modifiers: ('Alt' | 'Shift')[] = []) {
  const b = (await page.getByTestId('render-pane').boundingBox())!;
  await page.mouse.move(b.x + fx * b.width, b.y + fy * b.height);
  for (const m of modifiers) await page.keyboard.down(m);
  await page.mouse.down();
  await page.mouse.up();
  for (const m of modifiers) await page.keyboard.up(m);
}

const panel = () => page.getByRole('region', { name: 'Explain this pixel' });
const inspectButton = () => page.getByRole('button', { name: 'Inspect', exact: true });

appSessionForSuite((s) => ({ page } = s), {
  viewport: { width: 1600, height: 900 },
  query: '?test',
  // A wide render pane for the screenshot (the suite's default gives the graph 75 %).
  prepareContext: (context) => context.addInitScript(() => localStorage.setItem('kleinflow.split', '0.3')),
  ready: async () => {
    await page.getByRole('button', { name: 'Help' }).waitFor();
    await openExample('(2,3,7) hyperbolic tessellation');
    // Zoomed out a little: the docked panel leaves the disk's middle, where the orbit ends, in view.
    const b = (await page.getByTestId('render-pane').boundingBox())!;
    await page.mouse.move(b.x + b.width * 0.22, b.y + b.height / 2);
    await page.mouse.wheel(0, 240);
    await waitRendered(page);
  },
});

describe('Explain this pixel', () => {
  it('inspects a pixel of (2,3,7): the word is as long as the depth, and the GPU agrees', async () => {
    await inspectButton().click();
    await expect.poll(() => inspectButton().getAttribute('aria-pressed')).toBe('true');
    await clickPicture(0.25, 0.33);
    await panel().waitFor();
    const depth = Number(await page.getByTestId('inspect-depth').textContent());
    expect(depth).toBeGreaterThan(2);
    const word = panel().getByRole('list', { name: 'Word' }).getByRole('listitem');
    const powers = await word.evaluateAll((items) =>
      items.map((li) => Number(li.getAttribute('data-power'))),
    );
    expect(powers.reduce((a, b) => a + b, 0)).toBe(depth);
    expect(powers.length).toBe(depth); // mirrors only: every letter is one reflection
    await expect.poll(() => word.first().textContent()).toMatch(/Triangle kaleidoscope [123]/);
    expect(await panel().textContent()).toMatch(/Reached the tile \(the fundamental domain\)/);
    expect(await page.getByTestId('inspect-gpu').textContent()).toBe(`GPU depth: ${depth} (agrees)`);
    const markers = page.getByTestId('orbit-overlay').locator('.kf-orbit__marker');
    expect(await markers.count()).toBeGreaterThan(0);
    expect(await markers.count()).toBeLessThanOrEqual(depth);
    await page.screenshot({ path: SCREENSHOT });
  });

  it('Escape closes the panel, then leaves inspect mode', async () => {
    await page.keyboard.press('Escape');
    await panel().waitFor({ state: 'detached' });
    expect(await page.getByTestId('orbit-overlay').count()).toBe(0);
    expect(await inspectButton().getAttribute('aria-pressed')).toBe('true');
    await page.keyboard.press('Escape');
    await expect.poll(() => inspectButton().getAttribute('aria-pressed')).toBe('false');
    // Out of inspect mode a plain click explains nothing.
    await clickPicture(0.3, 0.38);
    await page.waitForTimeout(200);
    expect(await panel().count()).toBe(0);
  });

  it('Alt-click inspects without the toggle; a point outside the disk is explained as clipped', async () => {
    await clickPicture(0.02, 0.02, ['Alt']);
    await panel().waitFor();
    expect(await page.getByTestId('inspect-depth').textContent()).toBe('0');
    expect(await panel().textContent()).toMatch(/Outside the clip disk/);
    expect(await panel().getByRole('list', { name: 'Word' }).count()).toBe(0);
    await panel().getByRole('button', { name: 'Close' }).click();
    await panel().waitFor({ state: 'detached' });
  });

  it('in inspect mode a click on a handle inspects instead of moving it', async () => {
    await openExample('*333 kaleidoscope: drag the triangle');
    const before = await page.evaluate(() => JSON.stringify(window.__kleinflow!.store.getState().doc.nodes));
    const handle = page.locator('.kf-render-overlay circle').first();
    const box = (await handle.boundingBox())!;
    await inspectButton().click();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.up();
    await panel().waitFor();
    const after = await page.evaluate(() => JSON.stringify(window.__kleinflow!.store.getState().doc.nodes));
    expect(after).toBe(before);
    await inspectButton().click();
    await panel().waitFor({ state: 'detached' });
  });
});
