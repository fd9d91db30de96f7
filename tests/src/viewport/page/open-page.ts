/** Opens Chromium on a blank page with a <canvas> and the viewport harness (viewport-page.ts) loaded. */
import { fileURLToPath } from 'node:url';
import type { Browser, Page } from 'playwright-core';
import { launchChromium } from '../../../support/browser.ts';
import { bundle } from '../../../support/bundle.ts';

export interface HarnessPage {
  readonly browser: Browser;
  readonly page: Page;
  /** Page errors and console errors, to assert that none happened. */
  readonly errors: string[];
}

export async function openHarness(width = 400, height = 300): Promise<HarnessPage> {
  const script = await bundle(fileURLToPath(new URL('./viewport-page.ts', import.meta.url)));
  const browser = await launchChromium();
  const page = await browser.newPage({ viewport: { width: width + 40, height: height + 40 } });
  const errors: string[] = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.setContent(
    '<!doctype html><body style="margin:0"><div id="host" style="position:absolute;left:0;top:0"><canvas style="display:block"></canvas></div></body>',
  );
  await page.addScriptTag({ content: script });
  return { browser, page, errors };
}

export const decode = (b64: string | null): Uint8Array => {
  if (b64 === null) throw new Error('no image');
  return new Uint8Array(Buffer.from(b64, 'base64'));
};
