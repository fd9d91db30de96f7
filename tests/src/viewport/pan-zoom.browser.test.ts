/**
 * attachPanZoom in real Chromium, with the mouse like a user (and synthetic touch pointers for the
 * pinch): the world point that was under the cursor stays under it.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { View } from '../../../nodes/core/scene.ts';
import { circlesScene } from './fixtures.ts';
import { type HarnessPage, openHarness } from './page/open-page.ts';

// The canvas is 400 × 300 CSS px at the page's top-left; the view spans 3 world units of height.
const W = 400;
const H = 300;
let h: HarnessPage;
let page: Page;

beforeAll(async () => {
  h = await openHarness(W, H);
  page = h.page;
  await page.evaluate(([w, ht]) => window.kfViewport.create(w, ht, Number.POSITIVE_INFINITY), [
    W,
    H,
  ] as const);
  await page.evaluate((s) => window.kfViewport.setScene(s), circlesScene());
  await page.evaluate(() => window.kfViewport.attachPanZoom());
});

afterAll(async () => {
  await h?.browser.close();
});

const view = () => page.evaluate(() => window.kfViewport.view());
const setView = (v: View) => page.evaluate((v) => window.kfViewport.setView(v), v);
/** World point under CSS pixel (x, y) (y down) for view v. */
const worldAt = (v: View, x: number, y: number) => [
  v.center[0] + ((x - W / 2) / H) * v.scale,
  v.center[1] + ((H / 2 - y) / H) * v.scale,
];
const touch = (type: 'pointerdown' | 'pointermove' | 'pointerup', id: number, x: number, y: number) =>
  page.evaluate(([t, i, x, y]) => window.kfViewport.touch(t, i, x, y), [type, id, x, y] as const);

describe('attachPanZoom', () => {
  it('drags the picture with the pointer', async () => {
    await setView({ center: [0, 0], scale: 3 });
    await page.mouse.move(200, 150);
    await page.mouse.down();
    await page.mouse.move(300, 90, { steps: 5 });
    await page.mouse.up();
    const v = await view();
    // The world point that was under (200, 150) is now under (300, 90).
    expect(v.scale).toBe(3);
    expect(worldAt(v, 300, 90)[0]).toBeCloseTo(0, 9);
    expect(worldAt(v, 300, 90)[1]).toBeCloseTo(0, 9);
    expect(v.center[0]).toBeCloseTo(-1, 9);
  });

  it('zooms about the cursor with the wheel', async () => {
    await setView({ center: [0.2, -0.1], scale: 3 });
    const before = worldAt(await view(), 100, 75);
    await page.mouse.move(100, 75);
    await page.mouse.wheel(0, 100);
    const v = await view();
    expect(v.scale).toBeCloseTo(3 * Math.exp(0.15), 9); // wheel down zooms out
    const after = worldAt(v, 100, 75);
    expect(after[0]).toBeCloseTo(before[0], 9);
    expect(after[1]).toBeCloseTo(before[1], 9);
    await page.mouse.wheel(0, -100);
    expect((await view()).scale).toBeCloseTo(3, 9);
  });

  it('pinches with two fingers about their midpoint', async () => {
    await setView({ center: [0, 0], scale: 3 });
    const mid = worldAt(await view(), 200, 150);
    await touch('pointerdown', 11, 150, 150);
    await touch('pointerdown', 12, 250, 150);
    await touch('pointermove', 11, 100, 150);
    await touch('pointermove', 12, 300, 150);
    const v = await view();
    expect(v.scale).toBeCloseTo(1.5, 9); // fingers twice as far apart: zoomed in 2×
    expect(worldAt(v, 200, 150)[0]).toBeCloseTo(mid[0], 9);
    // Lift one finger: the other pans on from where it is.
    await touch('pointerup', 12, 300, 150);
    await touch('pointermove', 11, 130, 150);
    expect(worldAt(await view(), 130, 150)[0]).toBeCloseTo(worldAt(v, 100, 150)[0], 9);
    await touch('pointerup', 11, 130, 150);
  });

  it('leaves drags the overlay claimed (defaultPrevented) alone, and detaches', async () => {
    await setView({ center: [0, 0], scale: 3 });
    await page.evaluate(() => window.kfViewport.claimPointerDowns(true));
    await page.mouse.move(200, 150);
    await page.mouse.down();
    await page.mouse.move(260, 150, { steps: 3 });
    await page.mouse.up();
    expect((await view()).center).toEqual([0, 0]);
    await page.evaluate(() => window.kfViewport.claimPointerDowns(false));
    await page.evaluate(() => window.kfViewport.detachPanZoom?.());
    await page.mouse.down();
    await page.mouse.move(300, 150, { steps: 3 });
    await page.mouse.up();
    await page.mouse.wheel(0, 100);
    expect(await view()).toEqual({ center: [0, 0], scale: 3 });
    expect(h.errors).toEqual([]);
  });
});
