/**
 * The classroom and first contact, in Chromium: the docked inspector and the graph toolbar never
 * cover a node (the panel resizes by drag or keyboard, remembers its width, Esc closes it); the
 * overlay's labels never overlap; presenting from the editor and the embed link are read-only;
 * on a phone, "Add node" adds a node by tapping alone.
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Locator, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { shareLinkFor } from '../../src/app/io/share-link.ts';
import { repoRoot, type ServedApp, serveApp } from './app-server.ts';
import { dropFile, openViaPicker, pasteText } from './io-page.ts';

const shots = join(repoRoot, 'test-artifacts');
const exampleText = (name: string) =>
  readFileSync(join(repoRoot, 'examples', `${name}.kleinflow.json`), 'utf8');

type Box = { x: number; y: number; width: number; height: number };
const intersects = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
const boxOf = async (l: Locator): Promise<Box> => {
  const b = await l.boundingBox();
  if (!b) throw new Error('not visible');
  return b;
};
/** The document in the store (the page is opened with `?test`). */
const docOf = (page: Page) =>
  page.evaluate(() => window.__kleinflow!.store.getState().doc) as Promise<GraphDoc>;
/** What an edit could change: nodes, wires and the text (the view may pan). */
const content = (d: GraphDoc) => JSON.stringify({ nodes: d.nodes, edges: d.edges, meta: d.meta });

/** Every button inside `root` has an accessible name (text or aria-label). */
async function unnamedButtons(root: Locator): Promise<number> {
  return root
    .getByRole('button')
    .evaluateAll(
      (bs) => bs.filter((b) => !(b.getAttribute('aria-label') ?? b.textContent ?? '').trim()).length,
    );
}

describe('classroom', () => {
  let app: ServedApp;
  const problems: string[] = [];
  const watch = (p: Page) => {
    p.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    p.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    return p;
  };
  const open = async (viewport: { width: number; height: number }, example: string) => {
    const page = watch(await (await app.newContext(viewport)).newPage());
    await page.goto(`${app.url}?test`);
    await openViaPicker(page, `${example}.kleinflow.json`, Buffer.from(exampleText(example)));
    // A phone opens on the Picture tab: the graph is one tap away.
    if (viewport.width < 700) await page.getByRole('tab', { name: 'Graph' }).click();
    await page.locator('.react-flow__node').first().waitFor();
    return page;
  };
  beforeAll(async () => {
    mkdirSync(shots, { recursive: true });
    app = await serveApp();
  });
  afterAll(() => app?.close());

  describe('desktop', () => {
    let page: Page;
    beforeAll(async () => {
      page = await open({ width: 1280, height: 800 }, 'kaleidoscope-333');
    });

    it('docks the inspector beside the canvas: it never covers the selected node, even the right-most', async () => {
      const nodes = page.locator('.react-flow__node');
      const boxes = await Promise.all((await nodes.all()).map(boxOf));
      const rightmost = boxes.indexOf(boxes.reduce((a, b) => (b.x > a.x ? b : a)));
      await nodes.nth(rightmost).locator('.kf-node__header').click();
      await page.getByRole('button', { name: 'Inspector' }).click();
      const inspector = page.getByRole('complementary', { name: 'Inspector' });
      await inspector.waitFor();
      // The graph pans (animated) to bring the node back into view beside the panel.
      await expect
        .poll(async () => intersects(await boxOf(inspector), await boxOf(nodes.nth(rightmost))), {
          timeout: 5_000,
        })
        .toBe(false);
      const node = await boxOf(nodes.nth(rightmost));
      const canvas = await boxOf(page.locator('.kf-graph'));
      expect(node.x + node.width).toBeLessThanOrEqual(canvas.x + canvas.width);
      expect(node.x).toBeGreaterThanOrEqual(canvas.x);
      await page.screenshot({ path: join(shots, 'classroom-inspector-docked.png') });
    });

    it('after Tidy, the toolbar buttons cover no node', async () => {
      await page.getByRole('button', { name: 'Tidy' }).click();
      await page.waitForTimeout(500); // the fit animation
      const tools = page.getByRole('toolbar', { name: 'Graph' });
      const buttons = await Promise.all((await tools.getByRole('button').all()).map(boxOf));
      // Add node, Tidy, Inspector, and the selection tools (Mute, Frame, Group, Ungroup).
      expect(buttons.length).toBe(7);
      const nodes = await Promise.all((await page.locator('.react-flow__node').all()).map(boxOf));
      for (const b of buttons) for (const n of nodes) expect(intersects(b, n)).toBe(false);
    });

    it('resizes the inspector by keyboard and by drag, remembers the width, and Esc closes it', async () => {
      const handle = page.getByRole('separator', { name: 'Resize inspector' });
      const inspector = page.getByRole('complementary', { name: 'Inspector' });
      const before = (await boxOf(inspector)).width;
      await handle.focus();
      await page.keyboard.press('ArrowLeft');
      await page.keyboard.press('ArrowLeft');
      expect((await boxOf(inspector)).width).toBeCloseTo(before + 32, 0);
      const h = await boxOf(handle);
      await page.mouse.move(h.x + h.width / 2, h.y + 200);
      await page.mouse.down();
      await page.mouse.move(h.x - 60, h.y + 200, { steps: 4 });
      await page.mouse.up();
      const wide = Number(await handle.getAttribute('aria-valuenow'));
      expect(wide).toBeGreaterThan(before + 32 + 40);
      expect(await unnamedButtons(page.getByRole('toolbar', { name: 'Graph' }))).toBe(0);
      expect(await unnamedButtons(inspector)).toBe(0);
      await page.reload();
      await page.locator('.react-flow__node').first().locator('.kf-node__header').click();
      await inspector.waitFor();
      expect(Number(await handle.getAttribute('aria-valuenow'))).toBe(wide);
      await handle.focus();
      await page.keyboard.press('Escape');
      await inspector.waitFor({ state: 'detached' });
      const toggle = page.getByRole('button', { name: 'Inspector' });
      expect(await toggle.getAttribute('aria-pressed')).toBe('false');
      expect(await toggle.evaluate((b) => b === document.activeElement)).toBe(true); // focus not lost
    });

    it('presenting is read-only: undo, delete, cut, paste, drop, a typed link and drags leave the graph alone', async () => {
      // An edit in the editor first, so that an undo would visibly change the graph.
      const count = await page.locator('.react-flow__node').count();
      await page.locator('.react-flow__node').last().locator('.kf-node__header').click();
      await page.keyboard.press('Delete');
      await expect.poll(() => page.locator('.react-flow__node').count()).toBe(count - 1);
      const before = content(await docOf(page));
      await page.getByRole('button', { name: 'Present' }).click();
      await page.getByTestId('present-mode').waitFor();
      await page.keyboard.press('End'); // the whole construction, with the picture
      for (const key of [
        'Control+z',
        'Control+Shift+z',
        'Control+y',
        'Delete',
        'Backspace',
        'Control+a',
        'Control+x',
        'Control+d',
        'Control+v',
      ])
        await page.keyboard.press(key);
      await page.getByRole('status').filter({ hasText: 'read-only' }).waitFor();
      await pasteText(page, exampleText('hyperbolic-237'));
      await dropFile(
        page,
        'other.kleinflow.json',
        Buffer.from(exampleText('hyperbolic-237')),
        'application/json',
      );
      // A share link typed into the address bar (only the hash changes) is refused and cleared.
      const other = JSON.parse(exampleText('hyperbolic-237')) as GraphDoc;
      const typed = shareLinkFor(other, { origin: new URL(app.url).origin, pathname: '/' });
      if (!typed.ok) throw new Error(typed.message);
      await page.evaluate((hash) => {
        window.location.hash = hash;
      }, new URL(typed.url).hash);
      await expect.poll(() => page.evaluate(() => window.location.hash)).toBe('');
      await page.getByRole('status').filter({ hasText: 'read-only' }).waitFor();
      expect(await page.getByTestId('present-mode').count()).toBe(1);
      expect(await page.locator('[data-handle]').count()).toBe(0);
      const stage = await boxOf(page.getByTestId('render-pane'));
      await page.mouse.move(stage.x + stage.width / 2, stage.y + stage.height / 2);
      await page.mouse.down();
      await page.mouse.move(stage.x + stage.width / 2 + 80, stage.y + stage.height / 2 + 40, { steps: 5 });
      await page.mouse.up();
      await page.waitForTimeout(500);
      expect(content(await docOf(page))).toBe(before);
      await page.screenshot({ path: join(shots, 'classroom-present-read-only.png') });
      // Leaving restores editing: the undo that was refused now works.
      await page.keyboard.press('Escape');
      await page.locator('.react-flow__node').first().waitFor();
      await page.keyboard.press('Control+z');
      await expect.poll(() => page.locator('.react-flow__node').count()).toBe(count);
    });

    it('labels on the picture never overlap, on an example with many labelled circles, zoomed out too', async () => {
      const p = await open({ width: 1280, height: 800 }, 'rectangle-2222-wallpaper');
      const labels = p.locator('.kf-overlay-label');
      const check = async () => {
        await expect.poll(() => labels.count()).toBeGreaterThanOrEqual(3);
        const boxes = await labels.evaluateAll((ts) =>
          ts.map((t) => {
            const r = t.getBoundingClientRect();
            return { x: r.x, y: r.y, width: r.width, height: r.height, text: t.textContent };
          }),
        );
        const pane = await boxOf(p.getByTestId('render-pane'));
        for (const [i, a] of boxes.entries()) {
          expect(a.x >= pane.x && a.x + a.width <= pane.x + pane.width + 0.5, a.text ?? '').toBe(true);
          for (const b of boxes.slice(i + 1)) expect(intersects(a, b), `${a.text} / ${b.text}`).toBe(false);
        }
        return boxes.length;
      };
      const shown = await check();
      const pane = await boxOf(p.getByTestId('render-pane'));
      await p.mouse.move(pane.x + pane.width / 2, pane.y + pane.height / 2);
      for (let i = 0; i < 4; i++) await p.mouse.wheel(0, 240); // zoom out: the labels crowd together
      await p.waitForTimeout(600);
      await check();
      expect(shown).toBeGreaterThanOrEqual(3);
      await p.getByTestId('render-pane').screenshot({ path: join(shots, 'classroom-labels.png') });
      await p.close();
    });

    it('the embed link is read-only: no handles, a drag does not move anything, no edit controls', async () => {
      const doc = JSON.parse(exampleText('kaleidoscope-333')) as GraphDoc;
      const link = shareLinkFor(doc, { origin: new URL(app.url).origin, pathname: '/' });
      if (!link.ok) throw new Error(link.message);
      const p = watch(await (await app.newContext({ width: 800, height: 600 })).newPage());
      await p.goto(link.url.replace('/#', '/?mode=embed&test#'));
      await p.getByTestId('embed-mode').waitFor();
      await p.getByRole('img', { name: 'Construction overlay (read-only)' }).waitFor();
      await expect.poll(() => p.locator('[data-shape="point"]').count()).toBeGreaterThan(0);
      expect(await p.locator('[data-handle]').count()).toBe(0);
      const before = content(await docOf(p));
      const dot = await boxOf(p.locator('[data-shape="point"]').first());
      await p.mouse.move(dot.x + dot.width / 2, dot.y + dot.height / 2);
      await p.mouse.down();
      await p.mouse.move(dot.x + 90, dot.y + 60, { steps: 6 });
      await p.mouse.up();
      for (const key of ['Control+z', 'Delete', 'Control+v']) await p.keyboard.press(key);
      expect(content(await docOf(p))).toBe(before);
      // The only button is Fit (framing the picture changes nothing in the graph).
      const buttons = await p.getByRole('button').allTextContents();
      expect(buttons.filter((t) => !/^Fit/.test(t.trim()))).toEqual([]);
      expect(await p.getByRole('link', { name: 'Open in Kleinflow' }).count()).toBe(1);
      await p.close();
    });
  });

  it('on a 768 px tablet the docked inspector leaves the canvas room and the selection in view', async () => {
    const page = await open({ width: 768, height: 1024 }, 'kaleidoscope-333');
    const node = page.locator('.react-flow__node').first();
    await node.locator('.kf-node__header').click();
    await page.getByRole('button', { name: 'Inspector' }).click();
    const inspector = page.getByRole('complementary', { name: 'Inspector' });
    await inspector.waitFor();
    expect((await boxOf(page.locator('.kf-graph'))).width).toBeGreaterThanOrEqual(235);
    await expect
      .poll(async () => intersects(await boxOf(inspector), await boxOf(node)), { timeout: 5_000 })
      .toBe(false);
    await page.screenshot({ path: join(shots, 'classroom-tablet-inspector.png') });
    await page.close();
  });

  describe('phone 390×844', () => {
    let page: Page;
    beforeAll(async () => {
      page = await open({ width: 390, height: 844 }, 'kaleidoscope-333');
    });

    it('adds a node without a keyboard: Add node on the Graph tab, then tap a node type', async () => {
      await page.getByRole('tab', { name: 'Graph' }).click();
      await page.locator('.react-flow__node').first().waitFor();
      const count = await page.locator('.react-flow__node').count();
      const add = page.getByRole('button', { name: 'Add node' });
      const box = await boxOf(add);
      expect(box.x >= 0 && box.x + box.width <= 390 && box.y >= 0 && box.y + box.height <= 844).toBe(true);
      // The phone's inspector is its own tab: no toggle and no panel squeezing the canvas.
      expect(
        await page
          .getByRole('toolbar', { name: 'Graph' })
          .getByRole('button', { name: 'Inspector' })
          .isVisible(),
      ).toBe(false);
      await page.screenshot({ path: join(shots, 'classroom-phone-graph.png') });
      const palette = page.getByRole('dialog', { name: 'Add node' });
      await add.click();
      await palette.waitFor();
      await page.keyboard.press('Tab'); // the focus stays in the palette
      expect(await palette.evaluate((d) => d.contains(document.activeElement))).toBe(true);
      await page.keyboard.press('Escape'); // Esc closes it, nothing added
      await palette.waitFor({ state: 'detached' });
      expect(await page.locator('.react-flow__node').count()).toBe(count);
      await add.click();
      await palette.waitFor();
      const pbox = await boxOf(palette);
      expect(pbox.x >= 0 && pbox.x + pbox.width <= 390).toBe(true);
      await page.screenshot({ path: join(shots, 'classroom-phone-palette.png') });
      await palette
        .getByRole('option')
        .filter({ hasText: /^Circle/ })
        .first()
        .click();
      await palette.waitFor({ state: 'detached' });
      await expect.poll(() => page.locator('.react-flow__node').count()).toBe(count + 1);
      // The new node is selected (and, since keyboard-only construction, focused: an Esc now would
      // deselect it, as on any focused node); the Inspector tab shows it next.
      expect(await page.locator('.react-flow__node.selected').count()).toBe(1);
    });

    it('the Inspector tab shows the inspector over the whole pane', async () => {
      await page.getByRole('tab', { name: 'Inspector' }).click();
      const inspector = page.getByRole('complementary', { name: 'Inspector' });
      const box = await boxOf(inspector);
      expect(box.width).toBeGreaterThan(380);
      expect(box.height).toBeGreaterThan(600);
      await inspector.getByRole('heading', { name: 'Diagnostics' }).scrollIntoViewIfNeeded();
      expect(await inspector.getByRole('heading', { name: 'Diagnostics' }).isVisible()).toBe(true);
      await page.screenshot({ path: join(shots, 'classroom-phone-inspector.png') });
    });
  });

  it('no console errors', () => {
    expect(problems).toEqual([]);
  });
});
