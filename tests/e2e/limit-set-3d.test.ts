/**
 * Fig. 6 in real Chromium: the quaternion Kleinian group example draws its limit set as shaded dots
 * on the 3D view's overlay canvas (the painter of `kleinflow render`, shader-gen/space/
 * limit-dots-3d.ts), an orbit of the camera redraws them from the new point of view, and
 * Export → PNG carries them; a search cut short by `max words` says so in a live status.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { decodePng } from '../../src/io/png.ts';
import { repoRoot, type ServedApp } from './app-server.ts';
import { menu, openViaPicker } from './io-page.ts';
import { openSmall3dPane } from './view-3d-page.ts';

const ID = 'fig06-quaternion-kleinian-group';
const file = readFileSync(join(repoRoot, 'examples', '3d', `${ID}.kleinflow.json`));
const TITLE = JSON.parse(file.toString('utf8')).meta.title as string;
const SLOW = { timeout: 90_000 };

let app: ServedApp;
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

beforeAll(async () => {
  ({ app, page } = await openSmall3dPane());
  await openViaPicker(page, `${ID}.kleinflow.json`, file);
  await page.waitForFunction(
    (title) => window.__kleinflow!.store.getState().doc.meta.title === title,
    TITLE,
    SLOW,
  );
}, 240_000);

afterAll(async () => {
  await app?.close();
});

describe('the limit set of a quaternion Kleinian group in the 3D view', () => {
  it('paints the dots over the picture, and repaints them when the camera moves', async () => {
    await expect.poll(async () => (await dotPixels()).count, SLOW).toBeGreaterThan(200);
    const before = await dotPixels();
    expect(before.width).toBeGreaterThan(50);
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
    await menu(page, 'Export', 'PNG image');
    const dialog = page.getByRole('dialog', { name: 'Export PNG' });
    await dialog.getByLabel('Samples').fill('1');
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 120_000 }),
      dialog.getByRole('button', { name: /^Export \d+/ }).click(),
    ]);
    const image = decodePng(new Uint8Array(readFileSync((await download.path()) as string)));
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
