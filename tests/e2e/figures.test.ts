/**
 * The render node's figures in real Chromium: the Fig. 1 example draws its Cayley graph over the
 * live picture (coloured edges, the labels a–d), the depth-first Fig. 5 draws its limit set, and
 * Export → SVG and Export → PNG carry the figures.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { parseXml } from '../support/xml.ts';
import { appSessionForSuite } from './app-suite.ts';
import { waitRendered } from './editor-page.ts';
import { exportPng, menu, openExampleFile } from './io-page.ts';

let page: Page;
appSessionForSuite((s) => ({ page } = s), { ready: waitRendered });

const openExample = (id: string) => openExampleFile(page, id);

const overlay = () => page.getByTestId('figure-overlay');

describe('figures over the render', () => {
  it('draws the Cayley graph of Fig. 1 with its generator labels, and exports it as SVG', async () => {
    await openExample('fig01-cayley-graph');
    await expect.poll(() => overlay().locator('polyline').count(), { timeout: 30_000 }).toBeGreaterThan(50);
    const labels = await overlay().locator('text').allTextContents();
    expect([...labels].sort()).toEqual(['a', 'b', 'c', 'd']);
    const [download] = await Promise.all([page.waitForEvent('download'), menu(page, 'Export', 'SVG')]);
    const doc = parseXml(readFileSync((await download.path()) as string, 'utf8'));
    expect(doc.querySelectorAll('g.figures polyline').length).toBeGreaterThan(50);
    await expect.poll(() => page.getByTestId('toast').textContent()).toMatch(/figure strokes and points/);
  });

  it('draws the depth-first limit set of Fig. 5 as points and curves', async () => {
    await openExample('fig05-limit-set-depth-first');
    await expect
      .poll(
        async () =>
          (await overlay().locator('polyline').count()) + (await overlay().locator('circle').count()),
        {
          timeout: 30_000,
        },
      )
      .toBeGreaterThan(50);
    expect(await page.getByTestId('figure-note').count()).toBe(0);
  });

  it('paints the Cayley graph into the exported PNG (the generator colours are there)', async () => {
    await openExample('fig01-cayley-graph');
    await waitRendered(page);
    const image = await exportPng(page, { samples: 1 });
    // Pixels of the first generator's colour (#f24336, sRGB 0.95, 0.26, 0.21): only its edges have it.
    let red = 0;
    for (let i = 0; i < image.data.length; i += 4) {
      if (image.data[i] > 220 && image.data[i + 1] < 100 && image.data[i + 2] < 90) red++;
    }
    expect(red).toBeGreaterThan(100);
  }, 150_000);
});
