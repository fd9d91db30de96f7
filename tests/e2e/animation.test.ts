/**
 * "Export animation…" end to end in Chromium: the animated example exported from the dialog as a
 * GIF and (where this Chromium has a VP9/VP8 encoder) as a WebM; each file is decoded here and
 * holds exactly the frames asked for — one loop of the example (10 s) at 1 fps is 10 frames.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { ALL_FORMATS, BufferSource, Input } from 'mediabunny';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { countGifFrames, gifFrameBlocks } from '../../src/io/gif.ts';
import { repoRoot } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';
import { waitRendered } from './editor-page.ts';
import { menu, openViaPicker } from './io-page.ts';

let page: Page;
const problems: string[] = [];
const EXAMPLE = join(repoRoot, 'examples', 'animated-breathing-loxodromic.kleinflow.json');

appSessionForSuite((s) => ({ page } = s), {
  problems,
  async ready(p) {
    await waitRendered(p);
    await openViaPicker(p, 'animated.kleinflow.json', readFileSync(EXAMPLE));
    await waitRendered(p);
  },
});

/** Opens the dialog at 64 × 48, 1 fps, one loop, 2 samples, in `format`; returns the downloaded bytes. */
async function exportAs(format: string): Promise<{ name: string; bytes: Uint8Array }> {
  await menu(page, 'Export', 'Animation');
  const dialog = page.getByRole('dialog', { name: 'Export animation' });
  await dialog.getByLabel('Width in pixels').fill('64');
  await dialog.getByLabel('Height in pixels').fill('48');
  await dialog.getByLabel('Frames/s').fill('1');
  await dialog.getByLabel('Samples').fill('2');
  await dialog.getByLabel('One loop').check();
  await expect.poll(() => dialog.getByTestId('anim-loop-note').textContent()).toMatch(/10 s = 10 frames/);
  await dialog.locator('#kf-anim-format[data-checked="true"]').waitFor();
  await dialog.getByLabel('Format').selectOption(format);
  const [download] = await Promise.all([
    page.waitForEvent('download', { timeout: 120_000 }),
    dialog.getByRole('button', { name: 'Export 10 frames' }).click(),
  ]);
  await dialog.waitFor({ state: 'detached' });
  return {
    name: download.suggestedFilename(),
    bytes: new Uint8Array(readFileSync((await download.path())!)),
  };
}

describe('Export animation', () => {
  it('shows progress frame by frame, and Cancel stops it with no download', async () => {
    await menu(page, 'Export', 'Animation');
    const dialog = page.getByRole('dialog', { name: 'Export animation' });
    await dialog.locator('#kf-anim-format[data-checked="true"]').waitFor();
    await dialog.getByLabel('Format').selectOption('gif');
    await dialog.getByLabel('Duration in seconds').fill('60');
    let downloads = 0;
    const count = () => downloads++;
    page.on('download', count);
    await dialog.getByRole('button', { name: /^Export \d+ frames/ }).click();
    await dialog.getByText(/Rendering frame \d+ of 1440/).waitFor();
    await dialog.getByRole('button', { name: 'Cancel' }).click();
    await dialog.getByRole('button', { name: 'Export 1440 frames' }).waitFor();
    page.off('download', count);
    expect(downloads).toBe(0);
    await dialog.getByRole('button', { name: 'Close', exact: true }).click();
  }, 180_000);

  it('a GIF of one loop has one image per frame', async () => {
    const gif = await exportAs('gif');
    expect(gif.name).toMatch(/\.gif$/);
    expect(countGifFrames(gif.bytes)).toBe(10);
    // Each frame is its own time (t = i s): the spiral breathes, so the frames differ.
    const distinct = new Set(gifFrameBlocks(gif.bytes).map((b) => Buffer.from(b).toString('base64')));
    expect(distinct.size).toBe(10);
    expect(problems).toEqual([]);
  }, 180_000);

  it('every video format the browser can encode (WebM, MP4) holds the 10 frames; none: the dialog says why', async () => {
    await menu(page, 'Export', 'Animation');
    const dialog = page.getByRole('dialog', { name: 'Export animation' });
    // The encoder check runs once the dialog is open: wait for its answer.
    await dialog.locator('#kf-anim-format[data-checked="true"]').waitFor();
    const enabled = dialog.locator('#kf-anim-format option:not([disabled])');
    const formats = (await enabled.evaluateAll((os) => os.map((o) => (o as HTMLOptionElement).value))).filter(
      (f) => f !== 'gif',
    );
    if (formats.length === 0)
      await expect.poll(() => dialog.getByRole('status').textContent()).toMatch(/no WebCodecs video encoder/);
    await dialog.getByRole('button', { name: 'Close', exact: true }).click();
    for (const format of formats) {
      const video = await exportAs(format);
      expect(video.name).toMatch(format.startsWith('mp4') ? /\.mp4$/ : /\.webm$/);
      const input = new Input({ source: new BufferSource(video.bytes), formats: ALL_FORMATS });
      const track = await input.getPrimaryVideoTrack();
      expect(track, format).not.toBeNull();
      expect((await track!.computePacketStats()).packetCount, format).toBe(10);
      expect([track!.displayWidth, track!.displayHeight]).toEqual([64, 48]);
    }
    console.log(`video formats this Chromium encodes: ${formats.join(', ') || 'none'}`);
    expect(problems).toEqual([]);
  }, 300_000);
});
