/**
 * Shared by the 3D e2e suites: SwiftShader sphere-traces a full-size 3D pane for seconds a frame,
 * blocking the page, so they open the editor with a small render pane; and they look for pane
 * points away from the drawn handles (where a drag orbits the camera rather than grabbing).
 */
import type { BrowserContext, Page } from 'playwright-core';
import { type ServedApp, serveApp } from './app-server.ts';
import { waitRendered } from './editor-page.ts';

export interface Small3dSession {
  readonly app: ServedApp;
  readonly context: BrowserContext;
  readonly page: Page;
}

/**
 * The editor at 760 × 420 with the render pane 20 % of the width (about 150 × 350 px), opened and
 * its start-up picture rendered.
 */
export async function openSmall3dPane(): Promise<Small3dSession> {
  const app = await serveApp();
  const context = await app.newContext({ width: 760, height: 420 });
  await context.addInitScript(() => localStorage.setItem('kleinflow.split', '0.8'));
  const page = await context.newPage();
  page.setDefaultTimeout(90_000);
  await page.goto(`${app.url}?test`);
  await waitRendered(page);
  return { app, context, page };
}

/** The page-coordinate centre of every drawn handle knob. */
export const handleCentres = (page: Page): Promise<[number, number][]> =>
  page.locator('[data-handle]').evaluateAll((els) =>
    els.map((e) => {
      const r = e.getBoundingClientRect();
      return [r.x + r.width / 2, r.y + r.height / 2] as [number, number];
    }),
  );

/** A point of the render pane at least 20 px from every handle (where a drag orbits). */
export async function freePanePoint(page: Page): Promise<{ x: number; y: number }> {
  const b = (await page.getByTestId('render-pane').boundingBox())!;
  const handles = await handleCentres(page);
  for (const fy of [0.15, 0.3, 0.7, 0.85])
    for (const fx of [0.2, 0.5, 0.8]) {
      const p = { x: b.x + fx * b.width, y: b.y + fy * b.height };
      if (handles.every(([x, y]) => Math.hypot(x - p.x, y - p.y) > 20)) return p;
    }
  throw new Error('no free point in the render pane');
}
