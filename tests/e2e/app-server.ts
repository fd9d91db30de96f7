/**
 * The built app served for end-to-end suites: Vite builds once into a temp folder, `vite preview`
 * serves it on a free port, and Chromium (SwiftShader WebGL2) opens it. One set-up for every suite.
 */
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Browser, BrowserContext } from 'playwright-core';
import { build, type PreviewServer, preview } from 'vite';
import { launchChromium } from '../support/browser.ts';

export const repoRoot = join(import.meta.dirname, '..', '..');

export interface ServedApp {
  readonly url: string;
  readonly browser: Browser;
  /** A fresh context: downloads accepted, clipboard granted, render pane at 25% of the width. */
  newContext(viewport?: { width: number; height: number }): Promise<BrowserContext>;
  close(): Promise<void>;
}

export async function serveApp(): Promise<ServedApp> {
  const outDir = mkdtempSync(join(tmpdir(), 'kleinflow-e2e-'));
  await build({ root: repoRoot, logLevel: 'error', build: { outDir, emptyOutDir: true } });
  const server: PreviewServer = await preview({
    root: repoRoot,
    logLevel: 'error',
    build: { outDir },
    preview: { port: 0, host: '127.0.0.1' },
  });
  const url = server.resolvedUrls!.local[0];
  const browser = await launchChromium();
  return {
    url,
    browser,
    async newContext(viewport = { width: 1600, height: 960 }) {
      const context = await browser.newContext({ viewport, acceptDownloads: true });
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(url).origin });
      // A small render pane keeps SwiftShader fast: the graph gets 75% of the width.
      await context.addInitScript(() => {
        if (!localStorage.getItem('kleinflow.split')) localStorage.setItem('kleinflow.split', '0.75');
      });
      return context;
    },
    async close() {
      await browser.close();
      await new Promise((r) => server.httpServer.close(r));
      rmSync(outDir, { recursive: true, force: true });
    },
  };
}
