/**
 * The Add node button (no pointer position, the way a phone adds nodes): three Points added in a
 * row must not land on each other, and each stays in view, at 1280×720 and on a 390×844 phone. On
 * the phone, the zoom controls and minimap must leave the nodes' sockets free to tap. A paste with
 * the pointer over a node goes beside it: a copy on top hid the node and its header (the editor
 * e2e 'pastes nodes copied in another tab' then timed out clicking a covered header).
 */
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { repoRoot, type ServedApp } from './app-server.ts';
import { servedAppForSuite } from './app-suite.ts';
import { nodeCount } from './editor-page.ts';

let app: ServedApp;
servedAppForSuite((served) => {
  app = served;
});

type Box = { x: number; y: number; width: number; height: number };
const overlap = (a: Box, b: Box) =>
  a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
const inside = (a: Box, b: Box) =>
  a.x >= b.x && a.y >= b.y && a.x + a.width <= b.x + b.width && a.y + a.height <= b.y + b.height;

async function addPointWithButton(page: Page) {
  const before = await nodeCount(page);
  await page.getByRole('button', { name: 'Add node' }).click();
  const input = page.getByRole('combobox', { name: 'Search node types' });
  await input.fill('point');
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
  await expect.poll(() => nodeCount(page)).toBe(before + 1);
}

/** The sockets (handles) of the graph that are in the pane but covered by something else. */
const coveredSockets = (page: Page) =>
  page.evaluate(() => {
    const pane = document.querySelector('.kf-graph')!.getBoundingClientRect();
    return [...document.querySelectorAll('.react-flow__handle')]
      .map((h) => {
        const r = h.getBoundingClientRect();
        return { h, x: r.x + r.width / 2, y: r.y + r.height / 2 };
      })
      .filter(({ x, y }) => x > pane.left && x < pane.right && y > pane.top && y < pane.bottom)
      .filter(({ h, x, y }) => !h.contains(document.elementFromPoint(x, y)))
      .map(({ h }) => h.getAttribute('data-handleid'));
  });

describe.each([
  ['desktop', 1280, 720],
  ['phone', 390, 844],
])('Add node on %s', (device, width, height) => {
  it('places each new node where it covers no other, in view', async () => {
    const context = await app.newContext({ width, height });
    const page = await context.newPage();
    await page.goto(app.url);
    // A phone opens on the Picture tab; the graph is behind its own tab.
    if (device === 'phone') await page.getByRole('tab', { name: 'Graph' }).click();
    await expect.poll(() => nodeCount(page), { timeout: 30_000 }).toBeGreaterThan(0);
    if (device === 'phone') {
      // The default example's graph with every socket free (nothing parked over them).
      await expect.poll(() => coveredSockets(page), { timeout: 10_000 }).toEqual([]);
      await page.getByRole('button', { name: 'Menu' }).click();
      await page.getByRole('menuitem', { name: /^New/ }).click();
    } else await page.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => nodeCount(page)).toBe(0);
    for (let i = 0; i < 3; i++) await addPointWithButton(page);
    const pane = (await page.locator('.kf-graph').boundingBox())!;
    const nodes = page.locator('.react-flow__node');
    // Each new node is panned into view (an animation): wait for the last to be inside the pane.
    await expect
      .poll(async () => inside((await nodes.nth(2).boundingBox())!, pane), { timeout: 10_000 })
      .toBe(true);
    const boxes = await Promise.all([0, 1, 2].map(async (i) => (await nodes.nth(i).boundingBox())!));
    expect(overlap(boxes[0], boxes[1]) || overlap(boxes[0], boxes[2]) || overlap(boxes[1], boxes[2])).toBe(
      false,
    );
    expect(await coveredSockets(page)).toEqual([]);
    mkdirSync(join(repoRoot, 'test-artifacts'), { recursive: true });
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', `add-node-${device}.png`) });
    await context.close();
  }, 120_000);
});

describe('paste', () => {
  it('with the pointer over a node, the copy goes beside it and the node stays reachable', async () => {
    const context = await app.newContext({ width: 1280, height: 720 });
    const page = await context.newPage();
    await page.goto(app.url);
    const k = page.locator('.react-flow__node[data-id="k"]');
    await k.waitFor({ timeout: 30_000 });
    const before = await nodeCount(page);
    await k.locator('.kf-node__header').click();
    await page.keyboard.press('Control+c');
    const at = (await k.boundingBox())!;
    await page.mouse.move(at.x + 30, at.y + 10);
    await page.keyboard.press('Control+v');
    await expect.poll(() => nodeCount(page)).toBe(before + 1);
    const pasted = (await page.locator('.react-flow__node.selected').boundingBox())!;
    expect(overlap(pasted, (await k.boundingBox())!)).toBe(false);
    await k.locator('.kf-node__header').click({ timeout: 10_000 });
    await context.close();
  }, 120_000);
});
