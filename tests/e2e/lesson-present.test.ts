/**
 * A teacher's second lesson (issue #23, items 2 and 3), in Chromium: stepping through a
 * presentation reveals the construction — each mirror's hatched band appears at its own step and
 * the tiling at the Render step — in the editor's Present and in a `?mode=present` link alike; the
 * status bar's warnings list opens whole on screen (desktop and phone), names each node by its
 * title, and a click selects the node and pans the graph to it.
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { beforeAll, describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { presentLinks } from '../../src/app/present/present-link.ts';
import { repoRoot, type ServedApp } from './app-server.ts';
import { servedAppForSuite } from './app-suite.ts';
import { nodeEl } from './editor-page.ts';
import { openViaPicker } from './io-page.ts';

const shots = join(repoRoot, 'test-artifacts');
const k333 = (): GraphDoc =>
  JSON.parse(readFileSync(join(repoRoot, 'examples', 'kaleidoscope-333.kleinflow.json'), 'utf8'));

/** The *333 kaleidoscope with corner C pulled away: the angles are no longer 60°, a warning. */
function warped(): GraphDoc {
  const doc = k333();
  return {
    ...doc,
    nodes: doc.nodes.map((n) => (n.id === 'C' ? { ...n, params: { x: 0.3, y: 0.9 } } : n)),
  };
}

let app: ServedApp;
beforeAll(() => mkdirSync(shots, { recursive: true }));
servedAppForSuite((served) => {
  app = served;
});

async function openDoc(viewport: { width: number; height: number }, doc: GraphDoc): Promise<Page> {
  const page = await (await app.newContext(viewport)).newPage();
  await page.goto(`${app.url}?test`);
  await openViaPicker(page, 'lesson.kleinflow.json', Buffer.from(JSON.stringify(doc)));
  await page.waitForFunction(() => window.__kleinflow?.store.getState().doc.nodes.length === 11);
  return page;
}

/**
 * Walks every step with the arrow key from step 1 and checks, at each, that the overlay draws a
 * hatched band for exactly the mirrors built so far and that the picture shows from Render on.
 */
async function checkReveal(page: Page, name: string) {
  const list = page.getByRole('navigation', { name: 'Step list' });
  await list.waitFor();
  const labels = await list.locator('.kf-step-list__label').allTextContents();
  const render = labels.indexOf('Render');
  expect(render).toBeGreaterThan(0);
  const bands = () =>
    page
      .locator('[data-kept-side]')
      .evaluateAll((els) => new Set(els.map((e) => e.getAttribute('data-kept-side'))).size);
  const construction = () => page.locator('.kf-present--construction').count();
  await page.keyboard.press('Home');
  for (let step = 1; step <= labels.length; step++) {
    await page.keyboard.press('ArrowRight');
    await page
      .getByTestId('step-now')
      .filter({ hasText: `Step ${step} /` })
      .waitFor();
    const mirrors = labels.slice(0, step).filter((l) => l === 'Line reflection').length;
    await expect.poll(bands, { timeout: 10_000 }).toBe(mirrors);
    await expect.poll(construction, { timeout: 10_000 }).toBe(step > render ? 0 : 1);
    // No editor hint ("Wire a mirror …") over the audience's picture while mirrors are missing.
    expect(await page.getByTestId('render-hint').count()).toBe(0);
    if (step === 1) await page.screenshot({ path: join(shots, `${name}-step1.png`) });
  }
}

describe('presenting reveals the construction step by step', () => {
  it('in the editor: step 1 draws no mirror, each mirror appears at its step, the tiling at Render', async () => {
    const page = await openDoc({ width: 1280, height: 720 }, k333());
    await page.getByRole('button', { name: 'Present' }).click();
    await page.getByTestId('present-mode').waitFor();
    await checkReveal(page, 'lesson-present-editor');
    await page.context().close();
  }, 120_000);

  it('in a ?mode=present link, the same', async () => {
    const links = presentLinks(k333(), { origin: new URL(app.url).origin, pathname: '/' });
    if (!links.ok) throw new Error(links.message);
    const page = await (await app.newContext({ width: 1280, height: 720 })).newPage();
    await page.goto(links.present);
    await page.getByTestId('present-mode').waitFor();
    await checkReveal(page, 'lesson-present-link');
    await page.context().close();
  }, 120_000);
});

/** A point of bare canvas in the lower right of the graph pane, where a drag pans. */
async function bareCanvas(page: Page): Promise<{ x: number; y: number }> {
  const at = await page.evaluate(() => {
    const pane = document.querySelector('.kf-graph')!.getBoundingClientRect();
    for (let y = pane.bottom - 40; y > pane.top + 40; y -= 20)
      for (let x = pane.right - 40; x > pane.left + 40; x -= 20)
        if (document.elementFromPoint(x, y)?.classList.contains('react-flow__pane')) return { x, y };
    return null;
  });
  if (!at) throw new Error('no bare canvas in the graph pane');
  return at;
}

/** The diagnostics list lies wholly inside the window and is what the eye sees at its corners. */
async function expectListOnScreen(page: Page, shot: string) {
  const list = page.getByRole('list', { name: 'Diagnostics' });
  await list.waitFor();
  await page.screenshot({ path: join(shots, shot) });
  const seen = await list.evaluate((el) => {
    const r = el.getBoundingClientRect();
    const inset = 3;
    const corners = [
      [r.left + inset, r.top + inset],
      [r.right - inset, r.top + inset],
      [r.left + inset, r.bottom - inset],
      [r.right - inset, r.bottom - inset],
    ];
    return {
      inside: r.left >= 0 && r.top >= 0 && r.right <= innerWidth && r.bottom <= innerHeight,
      visible: corners.every(([x, y]) => el.contains(document.elementFromPoint(x, y))),
    };
  });
  expect(seen).toEqual({ inside: true, visible: true });
}

describe('the warnings list', () => {
  it('on a desktop: opens whole, names the node by its title, a click selects it and pans to it', async () => {
    const page = await openDoc({ width: 1280, height: 720 }, warped());
    const count = page.getByTestId('diagnostics-count');
    await count.filter({ hasText: /[1-9]\d* warnings?/ }).waitFor({ timeout: 30_000 });
    // Pan the graph well away (drags on bare canvas), so the node the warning is about is off screen.
    for (let i = 0; i < 3; i++) {
      const at = await bareCanvas(page);
      await page.mouse.move(at.x, at.y);
      await page.mouse.down();
      await page.mouse.move(at.x - 500, at.y - 300, { steps: 6 });
      await page.mouse.up();
    }
    await count.click();
    await expectListOnScreen(page, 'lesson-warnings-desktop.png');
    const entry = page.getByRole('list', { name: 'Diagnostics' }).getByRole('button').first();
    const name = (await entry.textContent())?.trim();
    await entry.click();
    const selected = () => page.evaluate(() => [...window.__kleinflow!.store.getState().selection].join(','));
    await expect.poll(selected).not.toBe('');
    const id = await selected();
    // The entry names the node by the title its header shows (its label, else its type's name).
    expect(name).toBe((await nodeEl(page, id).locator('.kf-node__title').textContent())?.trim());
    await expect.poll(() => nodeEl(page, id).getAttribute('class')).toMatch(/\bselected\b/);
    const graph = (await page.locator('.kf-graph').boundingBox())!;
    await expect
      .poll(
        async () => {
          const b = await nodeEl(page, id).boundingBox();
          return (
            !!b &&
            b.x >= graph.x &&
            b.y >= graph.y &&
            b.x + b.width <= graph.x + graph.width + 1 &&
            b.y < graph.y + graph.height
          );
        },
        { timeout: 10_000 },
      )
      .toBe(true);
    await page.context().close();
  }, 120_000);

  it('on a phone: opens whole on screen with readable entries', async () => {
    const page = await openDoc({ width: 390, height: 844 }, warped());
    const count = page.getByTestId('diagnostics-count');
    await count.filter({ hasText: /[1-9]\d* warnings?/ }).waitFor({ timeout: 30_000 });
    await count.click();
    await expectListOnScreen(page, 'lesson-warnings-phone.png');
    await page.context().close();
  }, 120_000);
});
