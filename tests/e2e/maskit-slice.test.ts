/**
 * The Maskit slice example, as a person uses it: a click in the render (press and release without
 * moving) places μ there — the node's μ and its read-out follow — as one undo step, while a drag on
 * empty space still pans and leaves μ alone. The page runs with `?test` (window.__kleinflow).
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { appSessionForSuite } from './app-suite.ts';
import { nodeEl } from './editor-page.ts';

const TITLE = 'The Maskit slice — a map of parameters';
let page: Page;

/** The slice node's μ and the document's view, through the test hooks. */
const state = () =>
  page.evaluate(() => {
    const doc = window.__kleinflow!.store.getState().doc;
    const slice = doc.nodes.find((n) => n.id === 'slice')!;
    return { mu: [...(slice.params.mu as number[])], center: [...doc.view.center], scale: doc.view.scale };
  });

appSessionForSuite((s) => ({ page } = s), {
  query: '?test',
  ready: async () => {
    await page.getByRole('button', { name: 'Examples' }).click();
    const gallery = page.getByRole('dialog', { name: 'Examples' });
    await gallery.locator('.kf-gallery__card').filter({ hasText: TITLE }).first().click();
    await gallery.waitFor({ state: 'detached' });
    await page.waitForFunction((t) => window.__kleinflow!.store.getState().doc.meta.title === t, TITLE);
    // One sample a pixel (not history): the test reads μ and the view, never the picture, and
    // SwiftShader re-accumulating 8 samples after every click and pan step blocks the page.
    await page.evaluate(() =>
      window.__kleinflow!.store.dispatchSilently({
        type: 'set-params',
        patches: [{ nodeId: 'out', params: { samples: 1 } }],
      }),
    );
  },
});

describe('Maskit slice', () => {
  it('a click in the pane places μ (one undo step); a drag on empty space pans instead', async () => {
    await expect.poll(() => page.getByLabel('Document title').inputValue()).toBe(TITLE);
    const before = await state();
    expect(before.mu).toEqual([-0.7, 1.95]);
    const pane = (await page.getByTestId('render-pane').boundingBox())!;
    // Away from the μ handle: a quarter across, a fifth down.
    const at = { x: pane.width * 0.25, y: pane.height * 0.2 };
    const { center, scale } = before;
    const want = [
      center[0] + ((at.x - pane.width / 2) / pane.height) * scale,
      center[1] + ((pane.height / 2 - at.y) / pane.height) * scale,
    ];
    await page.mouse.click(pane.x + at.x, pane.y + at.y);
    await expect.poll(async () => (await state()).mu).not.toEqual(before.mu);
    const placed = await state();
    // Within two pixels of the click (the pane's canvas may be a pixel off its box).
    const pixel = scale / pane.height;
    expect(Math.abs(placed.mu[0] - want[0])).toBeLessThan(2 * pixel);
    expect(Math.abs(placed.mu[1] - want[1])).toBeLessThan(2 * pixel);
    expect(placed.center).toEqual(before.center);
    // The node's read-out (its μ output) follows.
    await expect
      .poll(() => nodeEl(page, 'slice').textContent())
      .toContain(`μ = ${Number(placed.mu[0].toFixed(4))}`);

    // A drag on empty space pans: the view moves, μ does not.
    const from = { x: pane.x + pane.width * 0.7, y: pane.y + pane.height * 0.7 };
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 8; i++) await page.mouse.move(from.x - 5 * i, from.y - 3 * i);
    await page.mouse.up();
    const panned = await state();
    expect(panned.center).not.toEqual(before.center);
    expect(panned.mu).toEqual(placed.mu);

    // One undo puts μ back (pan/zoom is not history).
    await page.locator('.kf-graph').click({ position: { x: 10, y: 300 } });
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await state()).mu).toEqual(before.mu);
  }, 120_000);
});
