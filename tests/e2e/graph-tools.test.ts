/**
 * Graph tools end to end in Chromium: M mutes and unmutes a node (greyed, the picture changes,
 * undo restores it), a frame around two nodes carries them when its title bar is dragged, nodes
 * grouped with Ctrl+G light up their construction when the group is hovered, open (a frame made
 * inside stays in the group), lead back out by the breadcrumb and ungroup again, and a reroute point
 * is added to a wire, dragged and removed.
 */
import type { BrowserContext, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import type { ServedApp } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';
import {
  emptyCanvasPoint,
  nodeCount,
  nodeEl,
  type PixelStats,
  renderPixels,
  thumbDiff,
  waitRendered,
} from './editor-page.ts';
import { openViaPicker } from './io-page.ts';

let app: ServedApp;
let context: BrowserContext;
let page: Page;
const problems: string[] = [];
appSessionForSuite((s) => ({ app, context, page } = s), { problems });

const byType = (type: string) => page.locator(`.react-flow__node:has([data-node-type="${type}"])`).first();
/** The picture once it has all its samples and stopped changing (a re-render may not have begun yet). */
async function picture(): Promise<PixelStats> {
  // Off every node: a hovered node's construction is highlighted in the picture.
  const free = await emptyCanvasPoint(page);
  await page.mouse.move(free.x, free.y);
  let last: PixelStats | null = null;
  for (let i = 0; i < 20; i++) {
    await waitRendered(page);
    const now = await renderPixels(page);
    if (last && thumbDiff(last, now) < 0.5) return now;
    last = now;
    await page.waitForTimeout(250);
  }
  throw new Error('the picture never settled');
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

  it('Ctrl+G groups two nodes (same picture), the group opens, the breadcrumb leads out, Ctrl+Shift+G ungroups', async () => {
    // The frame from the previous test is undone; start from the example's nodes.
    const kaleido = (await byType('kaleidoscope').getAttribute('data-id'))!;
    const tile = (await byType('tile').getAttribute('data-id'))!;
    const before = await picture();
    const count = await page.locator('.react-flow__node-kf').count();
    await select(kaleido);
    await select(tile, true);
    await page.keyboard.press('Control+g');
    await expect.poll(() => page.locator('.react-flow__node-kf').count()).toBe(count - 1);
    await expect.poll(() => nodeEl(page, kaleido).count()).toBe(0);
    const group = page.locator('.react-flow__node:has([data-node-type="group"])');
    await expect.poll(() => group.count()).toBe(1);
    expect(thumbDiff(before, await picture())).toBeLessThan(2);

    // Hovering the group lights up what its inner nodes draw (the kaleidoscope's mirrors), by
    // their ids in the picture; off the group, nothing is highlighted.
    const halos = page.locator('.kf-render-overlay g[data-node]:has(> path[opacity="0.25"])');
    await expect.poll(() => halos.count()).toBe(0);
    await group.locator('.kf-node__header').hover();
    await expect
      .poll(() => halos.evaluateAll((gs) => [...new Set(gs.map((g) => g.getAttribute('data-node')))]))
      .toEqual([kaleido]);

    // A fresh session (the autosave) reopens the grouped document.
    const other = await context.newPage();
    await other.goto(app.url);
    await expect
      .poll(() => other.locator('.react-flow__node:has([data-node-type="group"])').count(), {
        timeout: 20_000,
      })
      .toBe(1);
    await other.close();

    await group.getByRole('button', { name: 'Open group' }).click();
    const crumbs = page.getByRole('navigation', { name: 'Open group' });
    await crumbs.waitFor();
    await expect.poll(() => page.locator('.react-flow__node-kf').count()).toBe(2);
    expect(await nodeEl(page, kaleido).count()).toBe(1);
    // A frame inside the group: made and titled there, kept in the group (not at the top level).
    // (The frame of the test before carried only these two nodes: it came inside with them.)
    const frames = page.getByRole('region', { name: /^Frame / });
    const framesBefore = await frames.count();
    await select(kaleido);
    await page.getByRole('button', { name: 'Frame', exact: true }).click();
    await expect.poll(() => frames.count()).toBe(framesBefore + 1);
    const title = frames.last().getByRole('textbox', { name: 'Frame title' });
    await title.fill('Mirrors');
    await title.press('Enter');
    await page.getByRole('region', { name: 'Frame Mirrors' }).waitFor();
    await crumbs.getByRole('button', { name: 'Graph' }).click();
    await crumbs.waitFor({ state: 'detached' });
    await expect.poll(() => page.locator('.react-flow__node-kf').count()).toBe(count - 1);
    expect(await page.getByRole('region', { name: 'Frame Mirrors' }).count()).toBe(0);
    await group.getByRole('button', { name: 'Open group' }).click();
    await page.getByRole('region', { name: 'Frame Mirrors' }).waitFor();
    await crumbs.getByRole('button', { name: 'Graph' }).click();
    await crumbs.waitFor({ state: 'detached' });

    await select((await group.getAttribute('data-id'))!);
    await page.keyboard.press('Control+Shift+g');
    await expect.poll(() => page.locator('.react-flow__node-kf').count()).toBe(count);
    expect(await nodeEl(page, kaleido).count()).toBe(1);
    expect(await nodeEl(page, tile).count()).toBe(1);
    // Ungrouped, the group's frame comes out with its node.
    await page.getByRole('region', { name: 'Frame Mirrors' }).waitFor();
    expect(thumbDiff(before, await picture())).toBeLessThan(2);
    expect(problems).toEqual([]);
  });

  it('double-clicking a wire adds a reroute point you can drag; double-clicking it removes it', async () => {
    const wire = page.locator('.react-flow__edge').first();
    const at = await center(wire);
    await page.mouse.dblclick(at.x, at.y);
    const dot = page.getByRole('button', { name: 'Reroute point' });
    await expect.poll(() => dot.count()).toBe(1);
    const from = await center(dot);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(from.x + 20, from.y + 40, { steps: 4 });
    await page.mouse.move(from.x + 40, from.y + 80, { steps: 4 });
    await page.mouse.up();
    await expect.poll(async () => (await center(dot)).y - from.y).toBeGreaterThan(60);
    await page.keyboard.press('Control+z');
    await expect.poll(async () => Math.abs((await center(dot)).y - from.y)).toBeLessThan(3);
    const back = await center(dot);
    await page.mouse.dblclick(back.x, back.y);
    await expect.poll(() => dot.count()).toBe(0);
    expect(problems).toEqual([]);
  });

  it('a problem inside a group: the group’s badge and the status list name the group and the node; inside, the node’s own', async () => {
    const broken = {
      format: 'kleinflow',
      version: 1,
      meta: { title: 'Broken group' },
      view: { center: [0, 0], scale: 4 },
      nodes: [
        {
          id: 'g',
          type: 'group',
          label: 'Mirror pair',
          position: [0, 0],
          params: {},
          group: {
            nodes: [
              { id: 'c', type: 'circle', label: 'Circle 2', position: [0, 0], params: { radius: -1 } },
              { id: 'i', type: 'inversion', position: [260, 0], params: {} },
            ],
            edges: [{ id: 'e1', from: { node: 'c', port: 'circle' }, to: { node: 'i', port: 'circle' } }],
            inputs: [],
            outputs: [{ name: 'element', from: { node: 'i', port: 'element' } }],
          },
        },
        { id: 'out', type: 'render', position: [400, 0], params: {} },
      ],
      edges: [{ id: 'e2', from: { node: 'g', port: 'element' }, to: { node: 'out', port: 'elements' } }],
    };
    await openViaPicker(page, 'broken.kleinflow.json', Buffer.from(JSON.stringify(broken)));
    const badge = nodeEl(page, 'g').locator('.kf-badge--error');
    await badge.waitFor();
    expect(await badge.getAttribute('title')).toMatch(/in group ‘Mirror pair’ → node ‘Circle 2’: /);
    await page.getByTestId('diagnostics-count').click();
    const list = page.getByRole('list', { name: 'Diagnostics' });
    // The entry names the group by its title (the list names nodes as their headers do).
    await expect
      .poll(() => list.textContent())
      .toMatch(/Mirror pair in group ‘Mirror pair’ → node ‘Circle 2’: /);
    await page.getByTestId('diagnostics-count').click();
    await nodeEl(page, 'g').getByRole('button', { name: 'Open group' }).click();
    const inner = nodeEl(page, 'c').locator('.kf-badge--error');
    await inner.waitFor();
    expect(await inner.getAttribute('title')).not.toMatch(/in group/);
    await page.getByRole('navigation', { name: 'Open group' }).getByRole('button', { name: 'Graph' }).click();
    expect(problems).toEqual([]);
  });
});
