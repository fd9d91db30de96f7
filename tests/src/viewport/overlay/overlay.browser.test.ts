/**
 * RenderOverlay in real Chromium, driven with the mouse like a user: drag a circle's centre and
 * rim, a point wired into a circle's centre, Shift-drag to the grid, Escape to cancel, hover.
 * The page (page/overlay-page.tsx) applies previews and commits the way the editor does.
 */
import { fileURLToPath } from 'node:url';
import type { Browser, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchChromium } from '../../../support/browser.ts';
import { bundle } from '../../../support/bundle.ts';
import type { LogEntry } from './page/overlay-page.tsx';

// The page's pane is 600 × 600 CSS px showing world [−2, 2]²: 150 px per unit, origin at (300, 300).
const css = (x: number, y: number): [number, number] => [300 + 150 * x, 300 - 150 * y];

let browser: Browser;
let page: Page;
let script: string;
const errors: string[] = [];

beforeAll(async () => {
  script = await bundle(fileURLToPath(new URL('./page/overlay-page.tsx', import.meta.url)));
  browser = await launchChromium();
  page = await browser.newPage({ viewport: { width: 640, height: 640 } });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  await page.setContent('<!doctype html><body style="margin:0"><div id="root"></div></body>');
  await page.addScriptTag({ content: script });
  await page.waitForSelector('[data-handle="c1/center"]');
});

afterAll(async () => {
  await browser?.close();
});

const nextFrame = () => page.evaluate(() => new Promise<void>((r) => requestAnimationFrame(() => r())));

/** Takes the log entries written since the last call. */
let seen = 0;
async function newEntries(): Promise<LogEntry[]> {
  const log = await page.evaluate(() => window.overlayLog);
  const fresh = log.slice(seen);
  seen = log.length;
  return fresh;
}

/** Presses at `from`, moves to `to` in `steps` frames, then (unless told otherwise) releases. */
async function drag(
  from: [number, number],
  to: [number, number],
  { steps = 6, release = true }: { steps?: number; release?: boolean } = {},
) {
  await newEntries();
  await page.mouse.move(...from);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    await page.mouse.move(
      from[0] + ((to[0] - from[0]) * i) / steps,
      from[1] + ((to[1] - from[1]) * i) / steps,
    );
    await nextFrame();
  }
  if (release) await page.mouse.up();
  await nextFrame();
  return newEntries();
}

const ofKind = <K extends LogEntry['kind']>(entries: LogEntry[], kind: K) =>
  entries.filter((e): e is Extract<LogEntry, { kind: K }> => e.kind === kind);

const handleAt = (id: string) =>
  page.$eval(`[data-handle="${id}"]`, (el) => [Number(el.getAttribute('cx')), Number(el.getAttribute('cy'))]);

describe('RenderOverlay in Chromium', () => {
  it('draws every shape with its label, and one grab handle per draggable spot', async () => {
    expect(
      await page.$$eval('[data-node][data-shape]', (gs) => gs.map((g) => (g as HTMLElement).dataset.node)),
    ).toEqual(['c1', 'c2', 'p2']);
    // p1 is hidden: no dot and no label "P", but c2's centre handle stands where it is.
    expect(await page.$$eval('.kf-overlay-label', (ts) => ts.map((t) => t.textContent))).toEqual(['C']);
    expect(await page.$$eval('[data-handle]', (hs) => hs.map((h) => h.getAttribute('data-handle')))).toEqual([
      'c1/center',
      'c1/rim',
      'c2/center',
      'c2/rim',
      'p2/point',
    ]);
  });

  it('drags a circle centre: previews while moving, one commit with the new centre', async () => {
    const entries = await drag(css(0, 0), css(0.3, 0.2));
    expect(ofKind(entries, 'pane-pointerdown')).toEqual([{ kind: 'pane-pointerdown', prevented: true }]);
    expect(ofKind(entries, 'preview').length).toBeGreaterThanOrEqual(3);
    const commits = ofKind(entries, 'commit');
    expect(commits).toHaveLength(1);
    expect(commits[0].patches).toHaveLength(1);
    expect(commits[0].patches[0].nodeId).toBe('c1');
    const [x, y] = commits[0].patches[0].params.center as number[];
    expect(x).toBeCloseTo(0.3, 9);
    expect(y).toBeCloseTo(0.2, 9);
    // The handles followed (the rim moved with the centre).
    expect(await handleAt('c1/center')).toEqual(css(0.3, 0.2).map((v) => expect.closeTo(v, 6)));
    expect(await handleAt('c1/rim')).toEqual(css(1.3, 0.2).map((v) => expect.closeTo(v, 6)));
  });

  it('drags the rim: the radius changes', async () => {
    const entries = await drag(css(1.3, 0.2), css(1.5, 0.2));
    const commits = ofKind(entries, 'commit');
    expect(commits).toHaveLength(1);
    expect(commits[0].patches).toEqual([{ nodeId: 'c1', params: { radius: expect.closeTo(1.2, 9) } }]);
  });

  it('drags the centre of a circle wired from a point: the patch moves the upstream point', async () => {
    const entries = await drag(css(1, 1), css(1.2, 1.4));
    const commits = ofKind(entries, 'commit');
    expect(commits).toHaveLength(1);
    expect(commits[0].patches).toEqual([
      { nodeId: 'p1', params: { x: expect.closeTo(1.2, 9), y: expect.closeTo(1.4, 9) } },
    ]);
    // The wired circle's centre handle moved with its point.
    expect(await handleAt('c2/center')).toEqual(css(1.2, 1.4).map((v) => expect.closeTo(v, 6)));
  });

  it('snaps to the grid while Shift is held, and shows the grid', async () => {
    await page.keyboard.down('Shift');
    // From (−1, 1) towards (−0.853, 1.127): the grid step at 150 px/unit is 0.2.
    const during = await drag(css(-1, 1), [172, 131], { release: false });
    expect(await page.$('[data-snap="grid"]')).not.toBeNull();
    await page.mouse.up();
    await page.keyboard.up('Shift');
    await nextFrame();
    const entries = [...during, ...(await newEntries())];
    const last = ofKind(entries, 'preview').at(-1)!;
    expect(last.patches).toEqual([
      { nodeId: 'p2', params: { x: expect.closeTo(-0.8, 9), y: expect.closeTo(1.2, 9) } },
    ]);
    expect(ofKind(entries, 'commit')).toEqual([
      {
        kind: 'commit',
        patches: [{ nodeId: 'p2', params: { x: expect.closeTo(-0.8, 9), y: expect.closeTo(1.2, 9) } }],
      },
    ]);
    expect(await page.$('[data-snap]')).toBeNull();
  });

  it('cancels with Escape: the preview goes back to the original params and nothing is committed', async () => {
    const during = await drag(css(0.3, 0.2), css(-0.5, -0.5), { release: false });
    expect(ofKind(during, 'preview').length).toBeGreaterThan(0);
    await page.keyboard.press('Escape');
    await page.mouse.up();
    await nextFrame();
    const after = await newEntries();
    expect(ofKind(after, 'commit')).toEqual([]);
    expect(ofKind(after, 'preview')).toEqual([
      {
        kind: 'preview',
        patches: [{ nodeId: 'c1', params: { center: [0.3, 0.2].map((v) => expect.closeTo(v, 9)) } }],
      },
    ]);
    expect(await handleAt('c1/center')).toEqual(css(0.3, 0.2).map((v) => expect.closeTo(v, 6)));
  });

  it('hovers geometry and lets presses on empty space through to the pane', async () => {
    await newEntries();
    // On c1's rim (centre (0.3, 0.2), radius 1.2), away from its handles.
    await page.mouse.move(...css(0.3, 1.4));
    await nextFrame();
    // The editor fed the hover back: c1 is drawn highlighted (with a halo), c2 is not.
    expect(await page.$$eval('[data-node="c1"][data-shape="circle"] path', (ps) => ps.length)).toBe(3);
    expect(await page.$$eval('[data-node="c2"][data-shape="circle"] path', (ps) => ps.length)).toBe(2);
    await page.mouse.move(...css(-1.6, -1.6));
    await page.mouse.down();
    await page.mouse.move(...css(-1.5, -1.5));
    await page.mouse.up();
    await nextFrame();
    const entries = await newEntries();
    expect(ofKind(entries, 'hover').map((e) => e.id)).toEqual(['c1', null]);
    expect(ofKind(entries, 'pane-pointerdown')).toEqual([{ kind: 'pane-pointerdown', prevented: false }]);
    expect(ofKind(entries, 'commit')).toEqual([]);
    expect(errors).toEqual([]);
  });

  it('Shift-drags a rim into tangency with the neighbouring circle', async () => {
    // c1: centre (0.3, 0.2), r 1.2; c2: centre (1.2, 1.4), r 0.5, so |c1 − c2| = 1.5 and the
    // rims touch at r = 1 (outside) or 2 (around). Releasing at r = 1.03 (4.5 px off) snaps to 1.
    await page.keyboard.down('Shift');
    const during = await drag(css(1.5, 0.2), css(1.33, 0.2), { release: false });
    expect(await page.$('[data-snap="tangent"]')).not.toBeNull();
    await page.mouse.up();
    await page.keyboard.up('Shift');
    await nextFrame();
    const entries = [...during, ...(await newEntries())];
    expect(ofKind(entries, 'commit')).toEqual([
      { kind: 'commit', patches: [{ nodeId: 'c1', params: { radius: expect.closeTo(1, 9) } }] },
    ]);
  });

  it('on a touch screen: one finger drags a handle, a second finger hands the gesture to the pane', async () => {
    const touchPage = await browser.newPage({ viewport: { width: 640, height: 640 }, hasTouch: true });
    await touchPage.setContent('<!doctype html><body style="margin:0"><div id="root"></div></body>');
    await touchPage.addScriptTag({ content: script });
    await touchPage.waitForSelector('[data-handle="c1/center"]');
    const cdp = await touchPage.context().newCDPSession(touchPage);
    const frame = () => touchPage.evaluate(() => new Promise<void>((r) => requestAnimationFrame(() => r())));
    const touch = async (type: 'touchStart' | 'touchMove' | 'touchEnd', points: [number, number][]) => {
      await cdp.send('Input.dispatchTouchEvent', {
        type,
        touchPoints: points.map(([x, y], id) => ({ x, y, id })),
      });
      await frame();
    };
    // One finger drags c1's centre from (0, 0) to (−0.4, 0).
    await touch('touchStart', [css(0, 0)]);
    for (const x of [-0.1, -0.2, -0.3, -0.4]) await touch('touchMove', [css(x, 0)]);
    await touch('touchEnd', []);
    // One finger on the centre, then a second finger lands: a pinch, not a drag.
    await touch('touchStart', [css(-0.4, 0)]);
    await touch('touchMove', [css(-0.2, 0)]);
    await touch('touchStart', [css(-0.2, 0), css(1, -1)]);
    await touch('touchMove', [css(-0.1, 0), css(1.2, -1.2)]);
    await touch('touchEnd', []);
    const log = await touchPage.evaluate(() => window.overlayLog);
    await touchPage.close();
    const commits = ofKind(log, 'commit');
    expect(commits).toEqual([
      {
        kind: 'commit',
        patches: [{ nodeId: 'c1', params: { center: [expect.closeTo(-0.4, 9), expect.closeTo(0, 9)] } }],
      },
    ]);
    expect(ofKind(log, 'pane-pointerdown').map((e) => e.prevented)).toEqual([true, true, false]);
    // The interrupted drag was put back where the first one left it.
    expect(ofKind(log, 'preview').at(-1)!.patches).toEqual([
      { nodeId: 'c1', params: { center: [expect.closeTo(-0.4, 9), expect.closeTo(0, 9)] } },
    ]);
  });
});
