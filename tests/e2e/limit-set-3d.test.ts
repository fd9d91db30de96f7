/**
 * Fig. 6 in real Chromium: the quaternion Kleinian group example draws its limit set as shaded dots
 * on the 3D view's overlay canvas (the painter of `kleinflow render`, shader-gen/space/
 * limit-dots-3d.ts), an orbit of the camera redraws them from the new point of view, and
 * Export → PNG carries them; a search cut short by `max words` says so in a live status.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { appSessionForSuite } from './app-suite.ts';
import { exportPng } from './io-page.ts';
import { open3dExample, openSmall3dPane } from './view-3d-page.ts';

const ID = 'fig06-quaternion-kleinian-group';
const SLOW = { timeout: 90_000 };

let page: Page;

/** The overlay canvas's opaque pixels, and a digest of where they are. */
const dotPixels = () =>
  page.getByTestId('limit-set-overlay').evaluate((c: HTMLCanvasElement) => {
    const data = c.getContext('2d')?.getImageData(0, 0, c.width, c.height).data;
    let count = 0;
    let where = 0;
    for (let i = 3; data && i < data.length; i += 4)
      if (data[i]! > 128) {
        count++;
        where = (where * 31 + i) % 1_000_003;
      }
    return { count, where, width: c.width };
  });

appSessionForSuite((s) => ({ page } = s), {
  open: openSmall3dPane,
  ready: (p) => open3dExample(p, ID),
  setupTimeout: 240_000,
});

describe('the limit set of a quaternion Kleinian group in the 3D view', () => {
  it('paints the dots over the picture, and repaints them when the camera moves', async () => {
    await expect.poll(async () => (await dotPixels()).count, SLOW).toBeGreaterThan(200);
    const before = await dotPixels();
    expect(before.width).toBeGreaterThan(50);
    // Searched in the worker, not on the main thread (which froze the editor for up to a second).
    expect(await page.getByTestId('limit-set-overlay').getAttribute('data-search')).toBe('worker');
    await page.evaluate(() =>
      window.__kleinflow!.store.dispatchSilently({
        type: 'set-camera-3d',
        camera: { position: [0.5, -3, 0.5], target: [0, 0, 0], fovDeg: 40 },
      }),
    );
    await expect.poll(async () => (await dotPixels()).where, SLOW).not.toBe(before.where);
    expect((await dotPixels()).count).toBeGreaterThan(200);
  });

  it('paints the dots into the exported PNG (the background alone is dark)', async () => {
    const image = await exportPng(page, { samples: 1 });
    let lit = 0;
    for (let i = 0; i < image.data.length; i += 4)
      if (Math.max(image.data[i]!, image.data[i + 1]!, image.data[i + 2]!) > 100) lit++;
    expect(lit).toBeGreaterThan(200);
  }, 150_000);

  it('says in a live status when the search stopped at max words', async () => {
    const status = page.getByTestId('limit-set-status');
    expect(await status.getAttribute('role')).toBe('status');
    expect(await status.textContent()).toBe('');
    const setWords = (maxWords: number) =>
      page.evaluate(
        (n) =>
          window.__kleinflow!.store.dispatchSilently({
            type: 'set-params',
            patches: [{ nodeId: 'group', params: { maxWords: n } }],
          }),
        maxWords,
      );
    await setWords(2000);
    await expect.poll(() => status.textContent(), SLOW).toMatch(/search stopped at 2000 words/);
    await setWords(1_000_000);
    await expect.poll(() => status.textContent(), SLOW).toBe('');
  }, 150_000);
});
