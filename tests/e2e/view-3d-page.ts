/**
 * Shared by the 3D e2e suites: SwiftShader sphere-traces a full-size 3D pane for seconds a frame,
 * blocking the page, so they open the editor with a small render pane; and they look for pane
 * points away from the drawn handles (where a drag orbits the camera rather than grabbing).
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { type AppSession, openAppSession, repoRoot } from './app-server.ts';
import { waitRendered } from './editor-page.ts';
import { openViaPicker } from './io-page.ts';

export type Small3dSession = AppSession;

/**
 * The editor at 760 × 420 with the render pane 20 % of the width (about 150 × 350 px), opened and
 * its start-up picture rendered.
 */
export async function openSmall3dPane(): Promise<Small3dSession> {
  const session = await openAppSession({
    viewport: { width: 760, height: 420 },
    query: '?test',
    prepareContext: (context) => context.addInitScript(() => localStorage.setItem('kleinflow.split', '0.8')),
    watchPage: (page) => page.setDefaultTimeout(90_000),
  });
  await waitRendered(session.page);
  return session;
}

/**
 * Opens examples/3d/`id`.kleinflow.json through the picker and waits (up to 90 s: the 3D pane
 * blocks the page while SwiftShader traces) until the store holds the example's title.
 */
export async function open3dExample(page: Page, id: string): Promise<void> {
  const file = readFileSync(join(repoRoot, 'examples', '3d', `${id}.kleinflow.json`));
  const title = JSON.parse(file.toString('utf8')).meta.title as string;
  await openViaPicker(page, `${id}.kleinflow.json`, file);
  await page.waitForFunction((t) => window.__kleinflow!.store.getState().doc.meta.title === t, title, {
    timeout: 90_000,
  });
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
