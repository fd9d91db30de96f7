/**
 * The app served for end-to-end suites, as users run it: `serveApp` builds once into a temp folder
 * and `vite preview` serves it (what `npm run build` ships); `serveDevApp` runs the dev server that
 * `npm start` runs (React StrictMode's double effects included, which a build never shows). Both
 * on a free port, opened by Chromium (SwiftShader WebGL2). One set-up for every suite.
 */
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { build, createServer, type PreviewServer, preview } from 'vite';
import { launchChromium } from '../support/browser.ts';

export const repoRoot = join(import.meta.dirname, '..', '..');

export interface ServedApp {
  readonly url: string;
  readonly browser: Browser;
  /**
   * A fresh context: downloads accepted, clipboard granted, render pane at 25% of the width, and
   * the first-visit welcome card already dismissed unless `firstVisit` asks for a brand-new browser.
   */
  newContext(
    viewport?: { width: number; height: number },
    options?: { firstVisit?: boolean },
  ): Promise<BrowserContext>;
  close(): Promise<void>;
}

export interface ServeOptions {
  /** More Chromium flags, e.g. `--use-fake-device-for-media-stream` for a fake camera. */
  readonly launchArgs?: readonly string[];
}

export async function serveApp(options: ServeOptions = {}): Promise<ServedApp> {
  const outDir = mkdtempSync(join(tmpdir(), 'kleinflow-e2e-'));
  await build({ root: repoRoot, logLevel: 'error', build: { outDir, emptyOutDir: true } });
  const server: PreviewServer = await preview({
    root: repoRoot,
    logLevel: 'error',
    build: { outDir },
    preview: { port: 0, host: '127.0.0.1' },
  });
  return openBrowserOn(
    server.resolvedUrls!.local[0],
    async () => {
      await new Promise((r) => server.httpServer.close(r));
      rmSync(outDir, { recursive: true, force: true });
    },
    options.launchArgs,
  );
}

/** The dev server exactly as `npm start` runs it (vite.config.ts, StrictMode), on a free port. */
export async function serveDevApp(): Promise<ServedApp> {
  const server = await createServer({
    root: repoRoot,
    logLevel: 'error',
    server: { port: 0, host: '127.0.0.1', strictPort: false, open: false },
  });
  await server.listen();
  return openBrowserOn(server.resolvedUrls!.local[0], () => server.close());
}

async function openBrowserOn(
  url: string,
  stopServer: () => Promise<void>,
  launchArgs: readonly string[] = [],
): Promise<ServedApp> {
  const browser = await launchChromium(launchArgs);
  return {
    url,
    browser,
    async newContext(viewport = { width: 1600, height: 960 }, options = {}) {
      const context = await browser.newContext({ viewport, acceptDownloads: true });
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(url).origin });
      // A small render pane keeps SwiftShader fast: the graph gets 75% of the width.
      await context.addInitScript((firstVisit) => {
        if (!localStorage.getItem('kleinflow.split')) localStorage.setItem('kleinflow.split', '0.75');
        if (!firstVisit) localStorage.setItem('kleinflow.welcome.dismissed', '1');
      }, options.firstVisit === true);
      return context;
    },
    async close() {
      await browser.close();
      await stopServer();
    },
  };
}

/** One suite's app, context and page (`app.close()` ends them all). */
export interface AppSession {
  readonly app: ServedApp;
  readonly context: BrowserContext;
  readonly page: Page;
}

export interface SessionOptions {
  readonly viewport?: { width: number; height: number };
  readonly query?: string;
  readonly problems?: string[];
  readonly consoleErrors?: boolean;
  /** Run on the new context before the page opens, e.g. to add an init script. */
  readonly prepareContext?: (context: BrowserContext) => Promise<unknown>;
  /** Run on the new page before it goes to the app, e.g. to listen to it. */
  readonly watchPage?: (page: Page) => unknown;
}

/**
 * The set-up most suites share: the built app (serveApp), a fresh context (`viewport`), and a page
 * opened at the app (`query`, e.g. '?test', after its address) whose page errors — and console
 * errors too with `consoleErrors` — are added to `problems`.
 */
export async function openAppSession(options: SessionOptions = {}): Promise<AppSession> {
  const app = await serveApp();
  const context = await app.newContext(options.viewport);
  await options.prepareContext?.(context);
  const page = await context.newPage();
  options.watchPage?.(page);
  const { problems } = options;
  if (problems) {
    if (options.consoleErrors)
      page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  }
  await page.goto(`${app.url}${options.query ?? ''}`);
  return { app, context, page };
}
