/**
 * One Chromium page with the GPU bench's browser side (gpu-page.ts, bundled) loaded as
 * `window.kfBench`: what the shader benches share. The browser is closed when `use` settles.
 */
import { fileURLToPath } from 'node:url';
import type { Page } from 'playwright-core';
import { launchChromium } from '../support/browser.ts';
import { bundle } from '../support/bundle.ts';

export async function withBenchPage<T>(use: (page: Page) => Promise<T>): Promise<T> {
  const script = await bundle(fileURLToPath(new URL('./gpu-page.ts', import.meta.url)));
  const browser = await launchChromium();
  try {
    const page = await browser.newPage();
    await page.setContent('<!doctype html><canvas width="1" height="1"></canvas>');
    await page.addScriptTag({ content: script });
    return await use(page);
  } finally {
    await browser.close();
  }
}
