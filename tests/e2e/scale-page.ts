/**
 * The editor at scale, shared by the scale e2e suite and the editor bench: a generated graph of
 * realistic mix (tests/bench/scale.ts) laid out like an opened file, opened the way a returning
 * user opens it (from the autosave), and a node dragged with real mouse moves while the page
 * records its animation-frame timestamps.
 */
import type { BrowserContext, Page } from 'playwright-core';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { registry } from '../../nodes/types/index.ts';
import { tidyIfOverlapping } from '../../src/editor/layout.ts';
import { AUTOSAVE_KEY } from '../../src/state/autosave.ts';
import { scaleGraph } from '../bench/scale.ts';

/** `nodes` nodes (points → lines/circles → mirrors/inversions → render) in the editor's tidy layout. */
export const editorScaleGraph = (nodes: number): GraphDoc => tidyIfOverlapping(scaleGraph(nodes), registry);

/**
 * Opens the app (`?test`) on `doc` through the autosave; resolves once React Flow shows its nodes.
 * Returns the milliseconds from navigation to nodes on screen.
 */
export async function openLarge(context: BrowserContext, url: string, doc: GraphDoc, timeout = 30_000) {
  await context.addInitScript(
    ([key, text]) => {
      if (!sessionStorage.getItem('kf-scale-opened')) localStorage.setItem(key, text);
      sessionStorage.setItem('kf-scale-opened', '1');
    },
    [AUTOSAVE_KEY, JSON.stringify(doc)] as const,
  );
  const page = await context.newPage();
  const t0 = Date.now();
  await page.goto(`${url}?test`);
  await page.locator('.react-flow__node').first().waitFor({ timeout });
  await page.waitForFunction(
    (n) => document.querySelectorAll('.react-flow__node').length >= n,
    doc.nodes.length,
    {
      timeout,
    },
  );
  return { page, openMs: Date.now() - t0 };
}

/** A node whose header lies inside the graph pane, away from its edges (to grab and drag). */
export async function draggableNode(page: Page): Promise<string> {
  const id = await page.evaluate(() => {
    const pane = document.querySelector('.kf-graph')!.getBoundingClientRect();
    for (const el of document.querySelectorAll('.react-flow__node')) {
      const h = el.querySelector('.kf-node__header')!.getBoundingClientRect();
      const inside =
        h.left > pane.left + 40 &&
        h.right < pane.right - 300 &&
        h.top > pane.top + 80 &&
        h.bottom < pane.bottom - 250;
      if (
        inside &&
        document
          .elementFromPoint(h.left + h.width / 2, h.top + h.height / 2)
          ?.closest('.react-flow__node') === el
      )
        return el.getAttribute('data-id');
    }
    return null;
  });
  if (!id) throw new Error('no node header is fully on screen');
  return id;
}

export interface DragResult {
  /** Intervals between animation frames while the pointer moved, ms. */
  readonly frameMs: number[];
  /** From the button's release until the next frame after the drop was committed, ms. */
  readonly dropMs: number;
  /** The node's position in the document before and after. */
  readonly from: readonly [number, number];
  readonly to: readonly [number, number];
}

const position = (page: Page, id: string) =>
  page.evaluate(
    (nodeId) => window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === nodeId)!.position,
    id,
  );

/** Drags node `id` by its header (dx, dy) screen pixels in `steps` mouse moves, timing the frames. */
export async function dragNode(
  page: Page,
  id: string,
  dx: number,
  dy: number,
  steps = 30,
): Promise<DragResult> {
  const from = await position(page, id);
  const box = (await page.locator(`.react-flow__node[data-id="${id}"] .kf-node__header`).boundingBox())!;
  const x = box.x + Math.min(40, box.width / 2);
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  // A string, not a function: tsx (the bench runner) would wrap a named inner function in a
  // `__name` helper that does not exist in the page.
  await page.evaluate(`(() => {
    window.__kfFrames = [];
    window.__kfFramesOn = true;
    const loop = (t) => {
      if (!window.__kfFramesOn) return;
      window.__kfFrames.push(t);
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  })()`);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) await page.mouse.move(x + (dx * i) / steps, y + (dy * i) / steps);
  const frames = await page.evaluate(() =>
    (window as unknown as { __kfFrames: number[] }).__kfFrames.slice(),
  );
  const released = await page.evaluate(() => performance.now());
  await page.mouse.up();
  // The drop is one document change: the editor re-evaluates the graph and the render takes the scene.
  const dropped = await page.evaluate(
    () => new Promise<number>((r) => requestAnimationFrame(() => requestAnimationFrame((t) => r(t)))),
  );
  await page.evaluate(() => {
    (window as unknown as { __kfFramesOn: boolean }).__kfFramesOn = false;
  });
  const frameMs = frames.slice(1).map((t, i) => t - frames[i]);
  return { frameMs, dropMs: dropped - released, from, to: await position(page, id) };
}

/** The q-quantile (0..1) of `xs`, nearest rank. */
export function quantile(xs: readonly number[], q: number): number {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))];
}
