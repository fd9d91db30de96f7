/**
 * The editor with a 500-node graph (realistic mix, 98 IIS elements) in real Chromium: it opens
 * (a hang guard, not a benchmark), React Flow shows every node, and a node dragged with 30 real
 * mouse moves follows the pointer and lands in the document as one undo step. Frame times are
 * reported by `npm run bench` (tests/bench/editor.ts), never asserted here.
 */
import { join } from 'node:path';
import type { BrowserContext, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { repoRoot, type ServedApp } from './app-server.ts';
import { servedAppForSuite } from './app-suite.ts';
import { draggableNode, dragNode, editorScaleGraph, openLarge } from './scale-page.ts';

const NODES = 500;
const doc = editorScaleGraph(NODES);

let app: ServedApp;
let context: BrowserContext;
let page: Page;
const problems: string[] = [];

servedAppForSuite(async (served) => {
  app = served;
  context = await app.newContext({ width: 1280, height: 720 });
});

describe('editor at scale', () => {
  it(`opens a ${NODES}-node graph and shows its nodes`, async () => {
    const opened = await openLarge(context, app.url, doc);
    page = opened.page;
    page.on('console', (m) => {
      if (m.type() === 'error') problems.push(`console: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    expect(opened.openMs).toBeLessThan(30_000);
    expect(await page.locator('.react-flow__node').count()).toBe(NODES);
    const shown = await page.evaluate(() => window.__kleinflow!.store.getState().doc.nodes.length);
    expect(shown).toBe(NODES);
    // Some nodes are on screen, not only in the DOM.
    await draggableNode(page);
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'scale-500-nodes.png') });
  }, 60_000);

  it('a node dragged with 30 mouse moves follows the pointer and is one undo step', async () => {
    const id = await draggableNode(page);
    const steps = await page.evaluate(() => window.__kleinflow!.store.getState().history.past.length);
    const zoom = await page.evaluate(() => {
      const m = /scale\(([\d.]+)\)/.exec(
        (document.querySelector('.react-flow__viewport') as HTMLElement).style.transform,
      );
      return m ? Number(m[1]) : 1;
    });
    const drag = await dragNode(page, id, 160, 90);
    expect(drag.frameMs.length).toBeGreaterThan(0);
    // The document moved by the pointer's travel in graph units (React Flow starts the drag a few
    // pixels in, past its drag threshold, and positions are rounded to whole units).
    expect(Math.abs(drag.to[0] - drag.from[0] - 160 / zoom)).toBeLessThan(16 / zoom);
    expect(Math.abs(drag.to[1] - drag.from[1] - 90 / zoom)).toBeLessThan(16 / zoom);
    expect(await page.evaluate(() => window.__kleinflow!.store.getState().history.past.length)).toBe(
      steps + 1,
    );
    expect(problems).toEqual([]);
  }, 120_000);
});
