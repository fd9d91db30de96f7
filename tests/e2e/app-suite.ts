/**
 * The set-up and tear-down every end-to-end suite repeats, registered in one call: before the
 * suite's first test the app is served (app-server.ts) and, for most suites, a page is opened on
 * it; after the last test the browser and the server are closed. A suite keeps what it uses
 * (`let page: Page;` … `appSessionForSuite((s) => ({ page } = s))`), so its tests read as before.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll } from 'vitest';
import {
  type AppSession,
  openAppSession,
  type ServedApp,
  type ServeOptions,
  type SessionOptions,
  serveApp,
} from './app-server.ts';

/** Building the app, starting Chromium and the first render take a while under load. */
const SETUP_TIMEOUT_MS = 180_000;

export interface SuiteSessionOptions extends SessionOptions {
  /** How the page opens (default: openAppSession with these options), e.g. openSmall3dPane. */
  readonly open?: () => Promise<AppSession>;
  /** What the page must have done before the first test, e.g. waitRendered. */
  readonly ready?: (page: Page) => Promise<unknown>;
  /** How long opening and `ready` may take (default SETUP_TIMEOUT_MS). */
  readonly setupTimeout?: number;
}

/**
 * A `ready` for suites about one node's inspector: `doc` loaded into the running app (as if
 * opened), node `nodeId` selected and the Inspector shown; the page waits up to a minute per step.
 */
export function inspectorOn(doc: unknown, nodeId: string): (page: Page) => Promise<void> {
  return async (page) => {
    page.setDefaultTimeout(60_000);
    await page.waitForFunction(() => window.__kleinflow?.store && window.__kleinflow.viewport);
    await page.evaluate(
      (d) => window.__kleinflow!.store.dispatch({ type: 'load-document', doc: d as never }),
      doc,
    );
    await page.evaluate((id) => window.__kleinflow!.store.setSelection([id]), nodeId);
    await page.getByRole('button', { name: 'Inspector' }).click();
  };
}

/** Before the suite: `open`, then `use` what it opened; after it: the app closed. */
function forTheSuite<T>(
  open: () => Promise<T>,
  appOf: (opened: T) => ServedApp,
  use: (opened: T) => unknown,
  timeout = SETUP_TIMEOUT_MS,
) {
  let app: ServedApp | undefined;
  beforeAll(async () => {
    const opened = await open();
    app = appOf(opened);
    await use(opened);
  }, timeout);
  afterAll(async () => {
    await app?.close();
  });
}

/** One served app for the suite (each test opens its own contexts on it); `use` may be async. */
export function servedAppForSuite(use: (app: ServedApp) => unknown, options: ServeOptions = {}): void {
  forTheSuite(
    () => serveApp(options),
    (app) => app,
    use,
  );
}

/** One app, context and page for the suite, handed to `use` and then made `ready`. */
export function appSessionForSuite(
  use: (session: AppSession) => void,
  options: SuiteSessionOptions = {},
): void {
  forTheSuite(
    options.open ?? (() => openAppSession(options)),
    (session) => session.app,
    async (session) => {
      use(session);
      await options.ready?.(session.page);
    },
    options.setupTimeout,
  );
}
