/**
 * Export → SVG in real Chromium: the Apollonian example downloads as a well-formed SVG full of
 * circles, with the count in the toast; a graph with a fold names the node that has no vector form.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { parseXml } from '../support/xml.ts';
import { appSessionForSuite } from './app-suite.ts';
import { waitRendered } from './editor-page.ts';
import { menu, openExampleFile } from './io-page.ts';

let page: Page;
appSessionForSuite((s) => ({ page } = s), { ready: waitRendered });

const openExample = (id: string) => openExampleFile(page, id);

describe('Export → SVG', () => {
  it('downloads the Apollonian gasket as an SVG of many circles and says how many', async () => {
    await openExample('apollonian-gasket');
    const [download] = await Promise.all([page.waitForEvent('download'), menu(page, 'Export', 'SVG')]);
    expect(download.suggestedFilename()).toMatch(/\.svg$/);
    const doc = parseXml(readFileSync((await download.path())!, 'utf8'));
    const circles = doc.documentElement.querySelectorAll(':scope > g circle').length;
    expect(circles).toBeGreaterThan(1000);
    const toast = await page.getByTestId('toast').textContent();
    const said = /(\d+) circles and lines/.exec(toast ?? '');
    expect(Number(said?.[1])).toBe(circles);
  });

  it('names the node that prevents a vector export, and downloads nothing', async () => {
    await openExample('glide-reflection-frieze');
    let downloaded = false;
    page.on('download', () => {
      downloaded = true;
    });
    await menu(page, 'Export', 'SVG');
    await expect
      .poll(() => page.getByTestId('toast').textContent())
      .toMatch(/No SVG: node "[^"]+" is a glide-reflection fold/);
    expect(downloaded).toBe(false);
  });
});
