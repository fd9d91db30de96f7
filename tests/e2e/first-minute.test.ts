/**
 * The first minute, as a newcomer meets it — against the dev server that `npm start` runs (React
 * StrictMode's double effects included: Help once closed itself there while the built app, which
 * the other suites use, worked) and against the built app. Help opens and stays open; the first
 * visit gets a welcome card that is remembered once dismissed; an empty or unfinished graph shows
 * a calm pane that says what is missing; the guided walkthrough ticks steps off as they are done.
 */
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { HINTS } from '../../src/app/render-hint.ts';
import { repoRoot, type ServedApp, serveApp, serveDevApp } from './app-server.ts';
import { addNode, connect, nodeCount, nodeEl, renderPixels, setField, waitRendered } from './editor-page.ts';

mkdirSync(join(repoRoot, 'test-artifacts'), { recursive: true });
const artifact = (name: string) => join(repoRoot, 'test-artifacts', name);

/** Two animation frames: every task queued before them (a stale dialog `close` event) has run. */
const settle = (page: Page) =>
  page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

const SERVERS: [string, () => Promise<ServedApp>][] = [
  ['dev server (npm start)', serveDevApp],
  ['built app', serveApp],
];

describe.each(SERVERS)('Help and dialogs — %s', (_name, serve) => {
  let app: ServedApp;
  let page: Page;
  beforeAll(async () => {
    app = await serve();
    page = await (await app.newContext({ width: 1280, height: 800 })).newPage();
    await page.goto(app.url);
    await page.getByRole('button', { name: 'Help' }).waitFor();
  });
  afterAll(() => app?.close());

  const help = () => page.getByRole('dialog', { name: 'Help' });

  it('opens Help from the ? button and it stays open, with the quick start, sockets, shortcuts and examples', async () => {
    await page.getByRole('button', { name: 'Help' }).click();
    await help().waitFor();
    await settle(page);
    expect(await help().isVisible()).toBe(true);
    for (const heading of [
      'Your first kaleidoscope in five steps',
      'Your first 3D picture in four steps',
      'Examples to open',
      'Socket colours',
      'Keyboard shortcuts',
    ])
      expect(await help().getByRole('heading', { name: heading }).isVisible()).toBe(true);
    const steps = help().locator('.kf-help__steps');
    expect(await steps.nth(0).locator('li').count()).toBe(5);
    expect(await steps.nth(1).locator('li').count()).toBe(4);
    await page.keyboard.press('Escape');
    await help().waitFor({ state: 'detached' });
  });

  it('opens Help with the ? key, and an example link opens that example', async () => {
    await page.locator('.kf-graph').click({ position: { x: 20, y: 300 } });
    await page.keyboard.press('?');
    await help().waitFor();
    await settle(page);
    expect(await help().isVisible()).toBe(true);
    await help()
      .getByRole('button', { name: /Apollonian gasket/ })
      .click();
    await help().waitFor({ state: 'detached' });
    await expect.poll(() => page.getByLabel('Document title').inputValue()).toMatch(/Apollonian/);
  });

  it('opens the PNG export dialog and it stays open', async () => {
    await page.getByRole('button', { name: 'Export' }).click();
    await page.getByRole('menuitem', { name: /PNG/ }).click();
    const dialog = page.getByRole('dialog', { name: 'Export PNG' });
    await dialog.waitFor();
    await settle(page);
    expect(await dialog.isVisible()).toBe(true);
    await dialog.getByRole('button', { name: 'Close export' }).click();
    await dialog.waitFor({ state: 'detached' });
  });
});

describe('first visit, unfinished graphs and the walkthrough — dev server (npm start)', () => {
  let app: ServedApp;
  let page: Page;
  beforeAll(async () => {
    app = await serveDevApp();
    page = await (await app.newContext({ width: 1920, height: 1080 }, { firstVisit: true })).newPage();
    await page.goto(app.url);
  });
  afterAll(() => app?.close());

  const welcome = () => page.getByRole('region', { name: 'Welcome to Kleinflow' });
  const hint = () => page.getByTestId('render-hint');

  it('greets a first visit with three ways in, and remembers the choice', async () => {
    await welcome().waitFor();
    for (const name of [
      'Build a kaleidoscope step by step',
      'Empty canvas',
      '(2,3,7) hyperbolic tessellation',
    ])
      expect(await welcome().getByRole('button', { name }).isVisible()).toBe(true);
    await page.screenshot({ path: artifact('welcome.png') });
    await welcome().getByRole('button', { name: 'Empty canvas' }).click();
    await welcome().waitFor({ state: 'detached' });
    await expect.poll(() => nodeCount(page)).toBe(0);
    await page.reload();
    await page.getByRole('button', { name: 'Help' }).waitFor();
    await settle(page);
    expect(await welcome().count()).toBe(0);
    // Escape dismisses it too (a fresh first visit in a new context).
    const other = await (await app.newContext({ width: 1400, height: 900 }, { firstVisit: true })).newPage();
    await other.goto(app.url);
    const card = other.getByRole('region', { name: 'Welcome to Kleinflow' });
    await card.waitFor();
    await other.keyboard.press('Escape');
    await card.waitFor({ state: 'detached' });
    await other.context().close();
  });

  it('frames the start-up example whole in a tall phone pane, as opening it from Examples does', async () => {
    const phone = await (await app.newContext({ width: 390, height: 844 }, { firstVisit: true })).newPage();
    await phone.goto(`${app.url}?test`);
    await phone.getByRole('region', { name: 'Welcome to Kleinflow' }).waitFor();
    const read = () =>
      phone.evaluate(() => {
        const pane = document.querySelector<HTMLElement>('[data-testid="render-pane"]')!;
        const k = (
          window as unknown as {
            __kleinflow: { store: { getState(): { doc: { view: { scale: number } } } } };
          }
        ).__kleinflow;
        return { w: pane.clientWidth, h: pane.clientHeight, scale: k.store.getState().doc.view.scale };
      });
    // The example is framed for a square pane of height 2.08 (the unit disk and a margin): in a
    // 390-wide pane the disk fits only when the pane's world height is 2.08 · H/W.
    await expect
      .poll(async () => {
        const { w, h, scale } = await read();
        return w > 0 && Math.abs(scale - (2.08 * h) / w) < 1e-6;
      })
      .toBe(true);
    await phone.context().close();
  });

  it('shows an empty graph as a calm pane that says what to do — never a flat error colour', async () => {
    await page.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => hint().textContent()).toBe(HINTS.empty);
    expect(await hint().getAttribute('class')).toContain('kf-render__hint--calm');
    const px = await renderPixels(page);
    expect(px.mean).toBeLessThan(40); // the dark theme background, not the palette's red
    const p = await addNode(page, 'point', 400, 300);
    expect(p).toBeTruthy();
    await expect.poll(() => hint().textContent()).toBe(HINTS.noRender);
    const render = await addNode(page, 'render', 700, 300);
    expect(render).toBeTruthy();
    await expect.poll(() => hint().textContent()).toBe(HINTS.noElements);
    expect(await page.getByTestId('diagnostics-count').textContent()).toMatch(/No problems/);
  });

  it('builds the (2,3,7) kaleidoscope from the empty canvas by following the Help quick start', async () => {
    await page.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => nodeCount(page)).toBe(0);
    // Step 1–2: the palette finds the nodes by the words the quick start uses.
    const k = await addNode(page, 'triangle', 340, 60);
    const render = await addNode(page, 'render', 700, 60);
    // Step 3: mirrors → elements gives a picture.
    await connect(page, k, 'elements', render, 'elements');
    await expect.poll(() => hint().count()).toBe(0);
    // Step 4: a tile colouring in parity.
    const tile = await addNode(page, 'tile colouring', 340, 400);
    await connect(page, tile, 'tile', render, 'tile');
    await nodeEl(page, tile).locator('select[aria-label="colouring"]').selectOption('parity');
    // Step 5: the disk frames it.
    await connect(page, k, 'boundary', render, 'clip');
    await waitRendered(page);
    const px = await renderPixels(page);
    expect(px.sd).toBeGreaterThan(30);
    expect(await page.getByTestId('diagnostics-count').textContent()).toMatch(/No problems/);
    expect(await nodeEl(page, k).locator('.kf-node__readout').textContent()).toMatch(/hyperbolic/);
  }, 120_000);

  it('walks a newcomer through the *333 kaleidoscope, ticking each step as it is done', async () => {
    await page.getByRole('button', { name: 'Help' }).click();
    await page.getByRole('button', { name: 'Build a kaleidoscope from points, step by step' }).click();
    const panel = page.getByRole('region', { name: 'Walkthrough' });
    await panel.waitFor();
    await expect.poll(() => nodeCount(page)).toBe(0);
    const done = () => panel.locator('[data-done="true"]').count();
    expect(await done()).toBe(0);

    // Corners of an equilateral triangle; the third line is drawn the wrong way round (A→C).
    const corners = [
      ['-1', '-0.5774'],
      ['1', '-0.5774'],
      ['0', '1.1547'],
    ];
    const rows = [30, 330, 630]; // graph-pane coordinates, right of the walkthrough panel
    const points: string[] = [];
    for (const [i, y] of rows.entries()) {
      const id = await addNode(page, 'point', 340, y);
      await setField(page, id, 'x', corners[i][0]);
      await setField(page, id, 'y', corners[i][1]);
      points.push(id);
    }
    await expect.poll(done).toBe(1);
    const lines: string[] = [];
    for (const y of rows) lines.push(await addNode(page, 'line', 600, y));
    const ends: [number, number][] = [
      [0, 1],
      [1, 2],
      [0, 2],
    ];
    for (const [i, [a, b]] of ends.entries()) {
      await connect(page, points[a], 'point', lines[i], 'a');
      await connect(page, points[b], 'point', lines[i], 'b');
    }
    await expect.poll(done).toBe(2);
    const mirrors: string[] = [];
    for (const y of rows) mirrors.push(await addNode(page, 'line reflection', 860, y));
    for (let i = 0; i < 3; i++) await connect(page, lines[i], 'line', mirrors[i], 'line');
    await expect.poll(done).toBe(3);
    const render = await addNode(page, 'render', 1150, 330);
    for (const m of mirrors) await connect(page, m, 'element', render, 'elements');
    await expect.poll(done).toBe(4);
    // The reversed line keeps the outside: the walkthrough names it and says how to fix it.
    await expect
      .poll(() => panel.locator('.kf-walkthrough__todo').textContent())
      .toMatch(/^Line reflection 3 keeps the outside/);
    await page.screenshot({ path: artifact('walkthrough.png') });
    await panel.getByRole('button', { name: 'Flip it' }).click();
    await expect
      .poll(() => nodeEl(page, mirrors[2]).locator('input[aria-label="flip"]').isChecked())
      .toBe(true);
    await expect.poll(done).toBe(5);
    expect(await panel.getByRole('status').textContent()).toMatch(/Done!/);
    expect(await hint().count()).toBe(0);
  }, 120_000);
});
