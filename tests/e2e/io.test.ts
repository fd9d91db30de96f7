/**
 * Every way in and out of the app, end to end in real Chromium (SwiftShader WebGL2): Save → Open
 * is lossless, share links round-trip (and broken or oversized ones leave the graph alone), the PNG
 * export matches the live view and reopens its graph, a Flower file drops in, paste opens a
 * document, the classroom mode steps through the construction, and user text is only ever text.
 */
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { deflateSync, strToU8 } from 'fflate';
import type { BrowserContext, Page } from 'playwright-core';
import { beforeAll, describe, expect, it } from 'vitest';
import { LIMITS } from '../../nodes/core/scene.ts';
import { evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';
import { compile } from '../../shader-gen/compile.ts';
import { encodeBase64Url } from '../../src/io/base64url.ts';
import { decodePng, encodePng } from '../../src/io/png.ts';
import { extractGraph } from '../../src/io/png-graph.ts';
import { AUTOSAVE_KEY } from '../../src/state/autosave.ts';
import { repoRoot, type ServedApp } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';
import { waitRendered } from './editor-page.ts';
import {
  boxDownscale,
  currentDoc,
  dropFile,
  livePixels,
  menu,
  openViaPicker,
  pasteText,
  saveViaButton,
  sideBySide,
} from './io-page.ts';

let app: ServedApp;
let context: BrowserContext;
let page: Page;
const problems: string[] = [];
const shots = join(repoRoot, 'test-artifacts');

function watch(p: Page): Page {
  p.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
  p.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  p.on('dialog', (d) => {
    problems.push(`dialog: ${d.message()}`);
    void d.dismiss();
  });
  return p;
}

const example = (id: string) => readFileSync(join(repoRoot, 'examples', `${id}.kleinflow.json`), 'utf8');
const report = (p: Page) => p.getByTestId('open-report');

beforeAll(() => {
  mkdirSync(shots, { recursive: true });
});
appSessionForSuite((s) => ({ app, context, page } = s), { watchPage: watch, ready: waitRendered });

describe('save and open', () => {
  it('Save downloads <title>.kleinflow.json and opening it is lossless and one undo step', async () => {
    const saved = await saveViaButton(page);
    expect(saved.name).toMatch(/\.kleinflow\.json$/);
    await openViaPicker(page, 'other.kleinflow.json', Buffer.from(example('kaleidoscope-333')));
    await expect
      .poll(async () => ((await currentDoc(page)) as { meta: { title: string } }).meta.title)
      .toBe(JSON.parse(example('kaleidoscope-333')).meta.title);
    await openViaPicker(page, saved.name, Buffer.from(saved.text));
    await expect.poll(() => currentDoc(page)).toEqual(JSON.parse(saved.text));
    await page.keyboard.press('Control+z');
    expect(((await currentDoc(page)) as { meta: { title: string } }).meta.title).toBe(
      JSON.parse(example('kaleidoscope-333')).meta.title,
    );
    await page.keyboard.press('Control+y');
    expect(await currentDoc(page)).toEqual(JSON.parse(saved.text));
  });

  it('a malformed file lists every problem with its path and leaves the graph untouched', async () => {
    const before = await currentDoc(page);
    const bad = JSON.parse(example('kaleidoscope-333'));
    bad.nodes[0].position = ['a', 1];
    bad.edges[0].from = 42;
    await openViaPicker(page, 'broken.kleinflow.json', Buffer.from(JSON.stringify(bad)));
    await report(page).waitFor();
    const text = await report(page).textContent();
    expect(text).toContain('nodes[0].position');
    expect(text).toContain('edges[0].from');
    expect(text).toContain('your graph is unchanged');
    await page.screenshot({ path: join(shots, 'io-open-report.png') });
    expect(await currentDoc(page)).toEqual(before);
    await report(page).getByRole('button', { name: 'Dismiss' }).click();
    await openViaPicker(page, 'notes.txt', Buffer.from('hello'), 'text/plain');
    expect(await report(page).textContent()).toContain('(document)');
    await report(page).getByRole('button', { name: 'Dismiss' }).click();
  });

  it('a Flower preset dropped on the window imports', async (ctx) => {
    const preset = join(repoRoot, '..', 'shared', 'reference', 'flower-presets', 'triangle.json');
    if (!existsSync(preset)) return ctx.skip();
    const overlay = await dropFile(page, 'triangle.json', readFileSync(preset), 'application/json');
    expect(overlay).toBe(true);
    await expect
      .poll(async () => ((await currentDoc(page)) as { nodes: unknown[] }).nodes.length)
      .toBeGreaterThan(0);
    expect(await page.getByTestId('drop-overlay').count()).toBe(0);
    await page.screenshot({ path: join(shots, 'io-flower-drop.png') });
    expect(await page.getByRole('button', { name: 'Undo' }).getAttribute('title')).toMatch(
      /open .*triangle\.json/,
    );
  });

  it('pasting a whole document opens it (copied nodes still paste as nodes)', async () => {
    const text = example('kaleidoscope-442');
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    await page.keyboard.press('Control+a');
    await page.keyboard.press('Control+c'); // nodes on the editor's clipboard must not paste too
    await pasteText(page, text);
    await expect.poll(() => currentDoc(page)).toEqual(JSON.parse(text));
    // React has committed and painted twice since: a late paste of the copied nodes would show now.
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    expect(await currentDoc(page)).toEqual(JSON.parse(text));
    expect(await page.getByRole('button', { name: 'Undo' }).getAttribute('title')).toContain('pasted graph');
  });
});

describe('share links', () => {
  it('Copy link → a new page opens the same graph; undo returns to the saved one; the fragment is cleared', async () => {
    const doc = await currentDoc(page);
    await menu(page, 'Export', 'Copy share link');
    await expect(page.getByTestId('toast').textContent()).resolves.toContain('Link copied');
    const link = await page.evaluate(() => navigator.clipboard.readText());
    expect(link).toMatch(/^http:\/\/127\.0\.0\.1:\d+\/#g=/);
    await page.evaluate(() => localStorage.setItem('kleinflow.split', '0.75'));
    const other = watch(await context.newPage());
    await other.goto(link);
    await expect.poll(() => currentDoc(other)).toEqual(doc);
    expect(await other.evaluate(() => location.hash)).toBe('');
    expect(await other.getByRole('button', { name: 'Undo' }).getAttribute('title')).toContain(
      'open shared link',
    );
    await other.close();
  });

  it('a broken link and an oversized or zip-bomb link give a message and keep the graph', async () => {
    const other = watch(await context.newPage());
    await other.goto(app.url);
    const before = await currentDoc(other);
    const bomb = encodeBase64Url(deflateSync(strToU8(' '.repeat(LIMITS.shareInflatedMaxBytes + 1000))));
    const cases: [string, RegExp][] = [
      ['#g=bm90LWRlZmxhdGU', /damaged|incomplete/],
      [`#g=${'A'.repeat(LIMITS.shareFragmentMaxChars + 10)}`, /too long/],
      [`#g=${bomb}`, /unpacks to more than/],
    ];
    for (const [fragment, message] of cases) {
      await other.goto(`${app.url}${fragment}`); // same document: the hashchange path
      await expect.poll(() => report(other).textContent()).toMatch(message);
      expect(await currentDoc(other)).toEqual(before);
    }
    await other.close();
  });
});

describe('PNG export', () => {
  /** The export is compared with a 512² live view, so the pane is made exactly that size. */
  async function squarePane(p: Page, side: number) {
    for (let i = 0; i < 3; i++) {
      const box = (await p.getByTestId('render-pane').boundingBox())!;
      if (Math.round(box.width) === side && Math.round(box.height) === side) return;
      const vp = p.viewportSize()!;
      await p.setViewportSize({
        width: Math.round(vp.width + (side - box.width) / 0.25),
        height: Math.round(vp.height + side - box.height),
      });
    }
  }

  it('exports a 4096² PNG matching the live view, with the graph inside that reopens', async () => {
    const SIDE = 512;
    const EXPORT = 4096;
    await squarePane(page, SIDE);
    await waitRendered(page);
    // Nothing in this file pans or zooms, so no view change is waiting to be stored: the graph the
    // export embeds must be exactly this one.
    const doc = await currentDoc(page);
    const live = await livePixels(page);
    expect([live.width, live.height]).toEqual([SIDE, SIDE]);

    await menu(page, 'Export', 'PNG image');
    const dialog = page.getByRole('dialog', { name: 'Export PNG' });
    await dialog.getByLabel('Size').selectOption({ label: '4096 × 4096' });
    await dialog.getByLabel('Samples').fill('4');
    await page.screenshot({ path: join(shots, 'io-export-dialog.png') });
    // Cancel stops the tiled render: no download, the dialog is ready again.
    let downloads = 0;
    const count = () => downloads++;
    page.on('download', count);
    await dialog.getByRole('button', { name: /^Export 4096/ }).click();
    await dialog.getByRole('progressbar').waitFor();
    await page.screenshot({ path: join(shots, 'io-export-progress.png') });
    await dialog.getByRole('button', { name: 'Cancel' }).click();
    await dialog.getByRole('button', { name: /^Export 4096/ }).waitFor();
    page.off('download', count);
    expect(downloads).toBe(0);

    const started = Date.now();
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 120_000 }),
      dialog.getByRole('button', { name: /^Export 4096/ }).click(),
    ]);
    const seconds = (Date.now() - started) / 1000;
    expect(download.suggestedFilename()).toMatch(/\.png$/);
    const bytes = new Uint8Array(readFileSync((await download.path())!));
    const image = decodePng(bytes);
    expect([image.width, image.height]).toEqual([EXPORT, EXPORT]);

    // The export has 64× the samples: at the fractal rim it is smooth where the live view aliases,
    // so pixels are compared away from the rim and, over the whole picture, as 8×8-pixel blocks.
    const small = boxDownscale(image, EXPORT / SIDE);
    writeFileSync(join(shots, 'io-export-vs-live.png'), encodePng(sideBySide(small, live)));
    const inner = meanDiff(small, live, (x, y) => Math.hypot(x - SIDE / 2, y - SIDE / 2) < SIDE * 0.3);
    const blocks = meanDiff(boxDownscale(small, 8), boxDownscale(live, 8), () => true);
    console.info(
      `4096² export: ${seconds.toFixed(1)} s; vs live 512²: mean |Δ| ${inner.toFixed(2)} (centre pixels), ${blocks.toFixed(2)} (8×8 blocks)`,
    );
    expect(inner).toBeLessThan(2.5); // one pixel of misalignment gives about 10
    expect(blocks).toBeLessThan(2);

    const embedded = extractGraph(bytes);
    expect(embedded.ok && embedded.doc).toEqual(doc);
    await openViaPicker(page, 'New construction', Buffer.from(example('kaleidoscope-333')));
    await dropFile(page, download.suggestedFilename(), Buffer.from(bytes), 'image/png');
    await expect.poll(() => currentDoc(page), { timeout: 20_000 }).toEqual(doc);
  }, 170_000);
});

type Rgba = { width: number; height: number; data: ArrayLike<number> };

/** Mean absolute RGB difference (0–255) of two same-size pictures over the pixels `where` picks. */
function meanDiff(a: Rgba, b: Rgba, where: (x: number, y: number) => boolean): number {
  let sum = 0;
  let n = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      if (!where(x, y)) continue;
      const i = (y * a.width + x) * 4;
      for (let c = 0; c < 3; c++) sum += Math.abs(a.data[i + c] - b.data[i + c]);
      n += 3;
    }
  }
  return sum / n;
}

/**
 * Present/embed have no status line: wait (through the `?test` hooks) until the viewport holds
 * every sample the render node asks for.
 */
const waitForPicture = (p: Page) =>
  p.waitForFunction(
    () => {
      const k = window.__kleinflow;
      const render = k?.store.getState().doc.nodes.find((n) => n.type === 'render');
      const target = Math.max(1, Number(render?.params.samples ?? 1));
      return (k?.viewport?.stats.frames ?? 0) > 0 && (k?.viewport?.stats.samples ?? 0) >= target;
    },
    undefined,
    { timeout: 60_000 },
  );

const XSS = '<img src=x onerror=alert(1)>';
const GLSL = '}; void main(){ #define X';

/** A document whose every user string is hostile. */
function hostileDoc(): string {
  const doc = JSON.parse(example('kaleidoscope-333'));
  doc.meta = { title: `${XSS} ${GLSL}`, description: `${GLSL}\n${XSS}` };
  doc.nodes = doc.nodes.map((n: Record<string, unknown>, i: number) => ({ ...n, label: i % 2 ? XSS : GLSL }));
  return JSON.stringify(doc);
}

describe('classroom and embed', () => {
  it('present mode shows the render without the graph and steps through the construction', async () => {
    const p = watch(await context.newPage());
    await p.setViewportSize({ width: 1100, height: 700 });
    await p.goto(app.url);
    await pasteText(p, example('kaleidoscope-333'));
    // Present mode opens the autosaved document: wait until the paste is in storage.
    await expect
      .poll(() => p.evaluate((key) => JSON.parse(localStorage.getItem(key) ?? 'null'), AUTOSAVE_KEY))
      .toEqual(JSON.parse(example('kaleidoscope-333')));
    await p.goto(`${app.url}?mode=present`);
    await p.getByTestId('present-mode').waitFor();
    expect(await p.locator('.react-flow').count()).toBe(0);
    const steps = p.getByTestId('step-now');
    const total = Number(((await steps.textContent()) ?? '').match(/Step (\d+) \/ (\d+)/)![2]);
    expect(total).toBeGreaterThan(3);
    expect(await steps.textContent()).toContain(`Step 1 / ${total}`); // a lesson starts at the beginning
    const drawn = () =>
      p.locator('.kf-render-overlay circle, .kf-render-overlay line, .kf-render-overlay path').count();
    await p.keyboard.press('End');
    await p.screenshot({ path: join(shots, 'io-present-full.png') });
    const all = await drawn();
    await p.keyboard.press('Home');
    expect(await steps.textContent()).toContain(`Step 0 / ${total}`);
    expect(await p.locator('.kf-present--construction').count()).toBe(1);
    const counts = [await drawn()];
    for (let i = 1; i <= total; i++) {
      await p.keyboard.press('ArrowRight');
      counts.push(await drawn());
      if (i === 3) {
        // The picture fades out while the construction is built: wait for the fade to end.
        await p.waitForFunction(
          () => getComputedStyle(document.querySelector('canvas.kf-render__canvas')!).opacity === '0',
        );
        await p.screenshot({ path: join(shots, 'io-present-step3.png') });
      }
    }
    expect(counts[0]).toBeLessThan(all);
    expect(counts.at(-1)).toBe(all);
    expect(counts.every((c, i) => i === 0 || c >= counts[i - 1])).toBe(true);
    expect(await p.locator('.kf-present--construction').count()).toBe(0);
    await p.getByRole('button', { name: 'Previous step' }).click();
    expect(await steps.textContent()).toContain(`Step ${total - 1} / ${total}`);
    await p.close();
  });

  it('embed mode shows only the render and an Open in Kleinflow link carrying the graph', async () => {
    const p = watch(await context.newPage());
    await p.setViewportSize({ width: 480, height: 320 });
    await p.goto(`${app.url}?mode=embed&test`);
    await p.getByTestId('embed-mode').waitFor();
    expect(await p.locator('.react-flow, .kf-topbar, .kf-steps').count()).toBe(0);
    expect(await p.getByRole('link', { name: 'Open in Kleinflow' }).getAttribute('href')).toMatch(/#g=/);
    await waitForPicture(p);
    await p.screenshot({ path: join(shots, 'io-embed.png') });
    await p.close();
  });

  it('titles, descriptions and labels are shown as text and never reach the shader', async () => {
    const text = hostileDoc();
    const loaded = parseDocumentText(text, registry);
    expect(loaded.ok).toBe(true);
    const source = compile(
      evaluateGraph(loaded.ok ? loaded.doc : (undefined as never), registry).scene,
    ).source;
    expect(source).not.toContain(XSS);
    expect(source).not.toContain('void main(){ #define');
    const p = watch(await context.newPage());
    await p.goto(app.url);
    await openViaPicker(p, `${XSS}.json`, Buffer.from(text));
    await expect.poll(() => p.getByRole('textbox', { name: 'Document title' }).inputValue()).toContain(XSS);
    expect(await p.locator('img[src="x"], [onerror]').count()).toBe(0);
    await p.goto(`${app.url}?mode=present`);
    await p.getByTestId('present-mode').waitFor();
    expect(await p.locator('.kf-present__title').textContent()).toContain(XSS);
    await p.keyboard.press('Home');
    await p.keyboard.press('ArrowRight');
    expect(await p.getByTestId('step-now').textContent()).toMatch(/void main|<img/);
    expect(await p.locator('img[src="x"], [onerror]').count()).toBe(0);
    await p.close();
    expect(problems.filter((m) => m.startsWith('dialog'))).toEqual([]);
  });

  it('no console errors on any page', () => {
    expect(problems).toEqual([]);
  });
});
