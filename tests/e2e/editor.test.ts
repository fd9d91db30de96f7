/**
 * The editor end to end in real Chromium (SwiftShader WebGL2): the app is built once with Vite,
 * served with `vite preview`, and driven with the mouse and keyboard like a person would.
 */
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { BrowserContext, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { EXAMPLES_3D_DIR, EXAMPLES_THUMB_DIR, exampleNames, examplePath } from '../../src/cli/examples.ts';
import { repoRoot, type ServedApp } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';
import {
  addNode,
  connect,
  edgeCount,
  emptyCanvasPoint,
  graphBox,
  handle,
  nodeCount,
  nodeEl,
  renderPixels,
  setField,
  thumbDiff,
  waitRendered,
} from './editor-page.ts';

let app: ServedApp;
let context: BrowserContext;
let page: Page;
const problems: string[] = [];

const titleOf = (name: string, dir?: string) =>
  JSON.parse(readFileSync(examplePath(name, dir), 'utf8')).meta?.title as string;
const exampleTitles = exampleNames().map((name) => titleOf(name));
/** The 3D examples are in the gallery too (their thumbnails come from the 3D renderer). */
const examples3d = exampleNames(EXAMPLES_3D_DIR);
const galleryTitles = [...exampleTitles, ...examples3d.map((name) => titleOf(name, EXAMPLES_3D_DIR))];
/** Every 2D example has a thumbnail (tests/examples/thumbnails.test.ts); 3D ones once rendered. */
const thumbCount =
  exampleTitles.length +
  examples3d.filter((name) => existsSync(join(EXAMPLES_THUMB_DIR, `${name}.png`))).length;

appSessionForSuite((s) => ({ app, context, page } = s), { problems, consoleErrors: true });

describe('editor', () => {
  it('opens on the default example and draws a picture', async () => {
    await expect.poll(() => nodeCount(page)).toBeGreaterThan(0);
    await waitRendered(page);
    const px = await renderPixels(page);
    expect(px.sd).toBeGreaterThan(20);
    expect(px.colours).toBeGreaterThan(3);
  });

  it('shows every example in the gallery, grouped, with a thumbnail, searchable, and loads them', async () => {
    const gallery = page.getByRole('dialog', { name: 'Examples' });
    const openGallery = async () => {
      await page.getByRole('button', { name: 'Examples' }).click();
      await gallery.waitFor();
    };
    await openGallery();
    const cards = gallery.locator('.kf-gallery__card');
    const listed = await cards.locator('strong').allTextContents();
    expect(listed.sort()).toEqual([...galleryTitles].sort());
    expect(await gallery.getByRole('heading', { name: 'Kaleidoscopes' }).isVisible()).toBe(true);
    expect(await gallery.getByRole('heading', { name: '3D' }).isVisible()).toBe(true);
    // Every card with a thumbnail shows it, loaded.
    const thumbs = gallery.locator('.kf-gallery__card img');
    expect(await thumbs.count()).toBe(thumbCount);
    await expect
      .poll(() => thumbs.evaluateAll((imgs) => imgs.every((i) => (i as HTMLImageElement).naturalWidth > 0)))
      .toBe(true);
    // The search box has the focus, so typing searches at once; Enter opens the first match.
    const search = gallery.getByRole('searchbox', { name: 'Search examples' });
    await expect.poll(() => search.evaluate((el) => el === document.activeElement)).toBe(true);
    await search.fill('schottky matrices');
    await expect.poll(() => cards.count()).toBe(1);
    const before = await page.getByLabel('Document title').inputValue();
    await page.keyboard.press('Enter');
    await gallery.waitFor({ state: 'detached' });
    await expect.poll(() => page.getByLabel('Document title').inputValue()).toMatch(/matrices/);
    // Loading replaced the graph: a toast says so and Ctrl+Z brings the graph back.
    expect(await page.getByTestId('toast').textContent()).toMatch(/Loaded .* Ctrl\+Z brings your graph back/);
    await page.locator('.kf-graph').click({ position: { x: 10, y: 200 } });
    await page.keyboard.press('Control+z');
    await expect.poll(() => page.getByLabel('Document title').inputValue()).toBe(before);
    // Loading each one costs a shader compile in SwiftShader: two are enough to show the cards work.
    for (const title of exampleTitles.filter((t) => !t.includes('(2,3,7)')).slice(0, 2)) {
      await openGallery();
      await cards.filter({ hasText: title }).first().click();
      await expect.poll(() => page.getByLabel('Document title').inputValue()).toBe(title);
      await waitRendered(page);
      expect((await renderPixels(page)).sd).toBeGreaterThan(5);
    }
    await openGallery();
    await cards.filter({ hasText: '(2,3,7) hyperbolic tessellation' }).click();
    await waitRendered(page);
    expect((await renderPixels(page)).sd).toBeGreaterThan(20);
  }, 120_000);

  it('adds a node through the palette and wires it', async () => {
    const nodes = await nodeCount(page);
    const edges = await edgeCount(page);
    const g = await graphBox(page);
    const refl = await addNode(page, 'line reflection', 40, g.height - 260);
    expect(await nodeCount(page)).toBe(nodes + 1);
    await connect(page, refl, 'element', 'out', 'elements');
    await expect.poll(() => edgeCount(page)).toBe(edges + 1);
  });

  it('a wire dropped on empty canvas opens the palette for fitting types and wires the pick', async () => {
    const nodes = await nodeCount(page);
    const edges = await edgeCount(page);
    const refl = await page.locator('.react-flow__node.selected').getAttribute('data-id');
    const from = (await handle(page, refl!, 'in', 'line').boundingBox())!;
    const empty = await emptyCanvasPoint(page);
    await page.mouse.move(from.x + 5, from.y + 5);
    await page.mouse.down();
    await page.mouse.move((from.x + empty.x) / 2, (from.y + empty.y) / 2, { steps: 5 });
    await page.mouse.move(empty.x, empty.y, { steps: 5 });
    await page.mouse.up();
    const input = page.getByRole('combobox', { name: 'Search node types' });
    await input.waitFor();
    const offered = await page.getByRole('option').allTextContents();
    expect(offered.length).toBeGreaterThan(0);
    expect(offered.some((t) => t.startsWith('Line'))).toBe(true);
    expect(offered.some((t) => t.startsWith('Point'))).toBe(false); // a point gives no line
    await input.fill('line');
    await page.keyboard.press('Enter');
    await expect.poll(() => nodeCount(page)).toBe(nodes + 1);
    await expect.poll(() => edgeCount(page)).toBe(edges + 1);
    // Delete removes the new node (and its wire) as one step; undo brings both back.
    await page.keyboard.press('Delete');
    await expect.poll(() => nodeCount(page)).toBe(nodes);
    expect(await edgeCount(page)).toBe(edges);
    await page.keyboard.press('Control+z');
    await expect.poll(() => edgeCount(page)).toBe(edges + 1);
  });

  it('scrubbing a number by dragging its label is one undo step', async () => {
    const field = nodeEl(page, 'k').locator('input[aria-label="size"]');
    const before = await field.inputValue();
    const label = (await nodeEl(page, 'k').locator('.kf-scrub', { hasText: 'size' }).boundingBox())!;
    await page.mouse.move(label.x + 5, label.y + label.height / 2);
    await page.mouse.down();
    for (let dx = 10; dx <= 60; dx += 10) await page.mouse.move(label.x + 5 + dx, label.y + label.height / 2);
    await page.mouse.up();
    await expect.poll(() => field.inputValue()).not.toBe(before);
    await page.keyboard.press('Control+z');
    await expect.poll(() => field.inputValue()).toBe(before);
  });

  it("shows only the tile's fields for its colouring mode; rare settings fold under More", async () => {
    const tile = nodeEl(page, 't');
    const labels = () => tile.locator('.kf-field__label, .kf-row__label').allTextContents();
    const mode = tile.locator('select[aria-label="colouring"]');
    const before = await mode.inputValue();
    await mode.selectOption('cosine');
    await expect.poll(labels).toContain('palette a');
    expect(await labels()).not.toContain('hue start');
    expect(await labels()).not.toContain('seeds only'); // folded under More
    await mode.selectOption('limit-set');
    await expect.poll(labels).toContain('limit glow px');
    expect(await labels()).not.toContain('palette a');
    await tile.getByRole('button', { name: 'more' }).click();
    await expect.poll(labels).toContain('seeds only');
    await tile.getByRole('button', { name: 'less' }).click();
    await expect.poll(labels).not.toContain('seeds only');
    // Hidden fields keep their values: two undos give the original mode and its rows back.
    await page.keyboard.press('Control+z');
    await page.keyboard.press('Control+z');
    await expect.poll(() => mode.inputValue()).toBe(before);
  });

  it('refuses an invalid connection, dimming the ports that cannot take it', async () => {
    const edges = await edgeCount(page);
    const from = handle(page, 't', 'out', 'tile');
    const to = handle(page, 'out', 'in', 'elements');
    const a = await from.boundingBox();
    await page.mouse.move(a!.x + 5, a!.y + 5);
    await page.mouse.down();
    await page.mouse.move(a!.x + 60, a!.y + 40, { steps: 3 });
    await expect.poll(() => to.getAttribute('class')).toMatch(/kf-port--dim/);
    expect(await handle(page, 'out', 'in', 'tile').getAttribute('class')).not.toMatch(/kf-port--dim/);
    const b = await to.boundingBox();
    await page.mouse.move(b!.x + 5, b!.y + 5, { steps: 3 });
    await page.mouse.up();
    expect(await edgeCount(page)).toBe(edges);
  });

  it('copies and pastes a node, then undo and redo walk it back and forth', async () => {
    const nodes = await nodeCount(page);
    await nodeEl(page, 'k').locator('.kf-node__header').click();
    await page.keyboard.press('Control+c');
    const g = await graphBox(page);
    await page.mouse.move(g.x + 500, g.y + 80);
    await page.keyboard.press('Control+v');
    await expect.poll(() => nodeCount(page)).toBe(nodes + 1);
    const pasted = await page.locator('.react-flow__node.selected').getAttribute('data-id');
    expect(pasted).not.toBe('k');
    expect(await nodeEl(page, pasted!).locator('.kf-node').getAttribute('data-node-type')).toBe(
      'kaleidoscope',
    );
    await page.keyboard.press('Control+z');
    await expect.poll(() => nodeCount(page)).toBe(nodes);
    await page.keyboard.press('Control+y');
    await expect.poll(() => nodeCount(page)).toBe(nodes + 1);
    await page.keyboard.press('Control+Shift+z');
    await page.keyboard.press('Control+z');
    await expect.poll(() => nodeCount(page)).toBe(nodes);
    await page.keyboard.press('Control+Shift+Z');
    await expect.poll(() => nodeCount(page)).toBe(nodes + 1);
  });

  it('autosaves: a reload brings the same graph back', async () => {
    const nodes = await nodeCount(page);
    const edges = await edgeCount(page);
    await page.getByTestId('save-state').filter({ hasText: 'Saved' }).waitFor();
    await page.reload();
    await expect.poll(() => nodeCount(page)).toBe(nodes);
    expect(await edgeCount(page)).toBe(edges);
  });

  // (After the reload test: the other tab autosaves too, and the last tab to save wins.)
  it('pastes nodes copied in another tab (through the system clipboard)', async () => {
    await nodeEl(page, 'k').locator('.kf-node__header').click();
    await page.keyboard.press('Control+c');
    const other = await context.newPage();
    try {
      await other.goto(page.url());
      await expect.poll(() => nodeCount(other)).toBeGreaterThan(0);
      const before = await nodeCount(other);
      const g = await graphBox(other);
      await other.mouse.move(g.x + 400, g.y + 60);
      await other.keyboard.press('Control+v');
      await expect.poll(() => nodeCount(other)).toBe(before + 1);
    } finally {
      await other.close();
    }
  });

  it('builds the *333 kaleidoscope from scratch, edits a point, undoes it and saves', async () => {
    await page.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => nodeCount(page)).toBe(0);
    // An equilateral triangle, counter-clockwise: each directed edge keeps the inside on its left.
    const corners: [string, string][] = [
      ['-1', '-0.5774'],
      ['1', '-0.5774'],
      ['0', '1.1547'],
    ];
    const rows = [30, 220, 410];
    const points: string[] = [];
    const lines: string[] = [];
    const mirrors: string[] = [];
    for (const [i, y] of rows.entries()) {
      const p = await addNode(page, 'point', 30, y);
      await setField(page, p, 'x', corners[i][0]);
      await setField(page, p, 'y', corners[i][1]);
      points.push(p);
    }
    for (const y of rows) lines.push(await addNode(page, 'line', 320, y));
    for (const y of rows) mirrors.push(await addNode(page, 'line reflection', 610, y));
    const render = await addNode(page, 'render', 900, 160);
    for (let i = 0; i < 3; i++) {
      await connect(page, points[i], 'point', lines[i], 'a');
      await connect(page, points[(i + 1) % 3], 'point', lines[i], 'b');
      await connect(page, lines[i], 'line', mirrors[i], 'line');
      await connect(page, mirrors[i], 'element', render, 'elements');
    }
    await expect.poll(() => edgeCount(page)).toBe(12);
    await expect
      .poll(() => nodeEl(page, render).locator('.kf-node__readout').textContent())
      .toBe('3 elements');
    expect(await page.getByTestId('diagnostics-count').textContent()).toMatch(/No problems|^0 errors/);
    // Zoom the render out (wheel over the picture) to see many tiles.
    const pane = (await page.getByTestId('render-pane').boundingBox())!;
    await page.mouse.move(pane.x + pane.width / 2, pane.y + pane.height / 2);
    for (let i = 0; i < 4; i++) await page.mouse.wheel(0, 300);
    await waitRendered(page);
    const tiling = await renderPixels(page);
    mkdirSync(join(repoRoot, 'test-artifacts'), { recursive: true });
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'editor-333.png') });
    expect(tiling.sd).toBeGreaterThan(30);
    expect(tiling.colours).toBeGreaterThan(20);

    // Move a corner by typing into its inline field: the picture changes; undo restores both.
    await setField(page, points[0], 'x', '-1.6');
    await waitRendered(page);
    const moved = await renderPixels(page);
    expect(thumbDiff(moved, tiling)).toBeGreaterThan(2);
    await page.mouse.click((await graphBox(page)).x + 1100, (await graphBox(page)).y + 700);
    await page.keyboard.press('Control+z');
    await expect.poll(() => nodeEl(page, points[0]).locator('input[aria-label="x"]').inputValue()).toBe('-1');
    await waitRendered(page);
    expect(thumbDiff(await renderPixels(page), tiling)).toBeLessThan(1);

    // Drag the same corner in the render, by its handle: the tiling follows and the node's x and y
    // change; one undo puts both the value and the picture back.
    const grip = (await page.locator(`[data-handle="${points[0]}/point"]`).first().boundingBox())!;
    const from = { x: grip.x + grip.width / 2, y: grip.y + grip.height / 2 };
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(from.x - 4 * i, from.y + 2 * i);
    await page.mouse.up();
    await expect
      .poll(() => nodeEl(page, points[0]).locator('input[aria-label="x"]').inputValue())
      .not.toBe('-1');
    expect(Number(await nodeEl(page, points[0]).locator('input[aria-label="x"]').inputValue())).toBeLessThan(
      -1,
    );
    expect(Number(await nodeEl(page, points[0]).locator('input[aria-label="y"]').inputValue())).toBeLessThan(
      -0.5774,
    );
    await waitRendered(page);
    expect(thumbDiff(await renderPixels(page), tiling)).toBeGreaterThan(2);
    await page.mouse.click((await graphBox(page)).x + 1100, (await graphBox(page)).y + 700);
    await page.keyboard.press('Control+z');
    await expect.poll(() => nodeEl(page, points[0]).locator('input[aria-label="x"]').inputValue()).toBe('-1');
    expect(Number(await nodeEl(page, points[0]).locator('input[aria-label="y"]').inputValue())).toBeCloseTo(
      -0.5774,
      3,
    );
    await waitRendered(page);
    expect(thumbDiff(await renderPixels(page), tiling)).toBeLessThan(1);

    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'editor.png') });

    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.getByRole('button', { name: 'Save' }).click(),
    ]);
    expect(download.suggestedFilename()).toMatch(/\.kleinflow\.json$/);
    const saved = parseDocumentText(readFileSync((await download.path())!, 'utf8'), registry);
    expect(saved.ok).toBe(true);
    if (saved.ok) {
      expect(saved.doc.nodes).toHaveLength(10);
      expect(saved.doc.edges).toHaveLength(12);
    }
  }, 150_000);

  it('an unreadable autosave is reported and offered for download, not thrown away', async () => {
    // Let the pending autosave land first (a reload flushes it), so it cannot overwrite the broken text.
    await page.getByTestId('save-state').filter({ hasText: 'Saved' }).waitFor();
    const broken = '{"format":"kleinflow","nodes":[oops';
    // Both copies: the tab's own (sessionStorage, read first on reload) and the one new tabs start from.
    await page.evaluate((text) => {
      localStorage.setItem('kleinflow.autosave', text);
      sessionStorage.setItem('kleinflow.tab.doc', text);
    }, broken);
    await page.reload();
    const banner = page.getByRole('alert').filter({ hasText: 'could not be restored' });
    await banner.waitFor();
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      banner.getByRole('button', { name: 'Download it' }).click(),
    ]);
    expect(readFileSync((await download.path())!, 'utf8')).toBe(broken);
    expect(await page.evaluate(() => localStorage.getItem('kleinflow.autosave.unreadable'))).toBe(broken);
    // The editor still works: it opened the default example.
    expect(await nodeCount(page)).toBeGreaterThan(0);
  });

  it('a full browser storage is reported, not ignored', async () => {
    await page.evaluate(() => {
      const setItem = Storage.prototype.setItem;
      Storage.prototype.setItem = function (key: string, value: string) {
        if (key === 'kleinflow.autosave') throw new DOMException('quota exceeded', 'QuotaExceededError');
        return setItem.call(this, key, value);
      };
    });
    await setField(page, 'k', 'size', '1.5');
    await page.getByRole('alert').filter({ hasText: 'storage is full' }).waitFor();
    expect(await page.getByTestId('save-state').textContent()).toBe('Not saved');
  });

  it('logged no console errors and no page errors', () => {
    expect(problems).toEqual([]);
  });
});
