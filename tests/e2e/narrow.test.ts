/**
 * Phone and tablet, against the dev server that `npm start` runs: at 390×844 (a phone) and
 * 768×1024 (a tablet in portrait) every top-bar command can be reached on screen — directly or
 * through a menu — the top bar stays inside the window, and the picture is in view. On the phone
 * the panes are tabs (Graph / Picture / Inspector) and the presentation fits the width.
 */
import { mkdirSync, readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Locator, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { repoRoot, type ServedApp, serveDevApp } from './app-server.ts';

const shots = join(repoRoot, 'test-artifacts');
/** The gallery's examples: examples/ and the 3D ones in examples/3d/. */
const EXAMPLE_TITLES = ['examples', 'examples/3d'].flatMap((dir) =>
  readdirSync(join(repoRoot, dir))
    .filter((f) => f.endsWith('.kleinflow.json'))
    .map((f) => {
      const doc = JSON.parse(readFileSync(join(repoRoot, dir, f), 'utf8'));
      return (doc.meta?.title as string | undefined) ?? f.replace(/\.kleinflow\.json$/, '');
    }),
);
const COMMANDS = [
  'Examples',
  'New',
  'Open…',
  'Save',
  'PNG image…',
  'Animation…',
  'SVG (circles and lines)',
  'Mesh (3D print)…',
  'Copy share link',
  'GLSL shader (.frag)',
  'Shadertoy (.shadertoy.glsl)',
  'Present',
  'Undo',
  'Redo',
  'Play animation',
  'Inspect',
  'Help',
];

/** Whether the element's box lies inside the window (and has a size). */
async function inView(page: Page, el: Locator): Promise<boolean> {
  const box = await el.boundingBox();
  const size = page.viewportSize()!;
  return (
    box !== null &&
    box.width > 0 &&
    box.height > 0 &&
    box.x >= 0 &&
    box.y >= 0 &&
    box.x + box.width <= size.width + 0.5 &&
    box.y + box.height <= size.height + 0.5
  );
}

/** The command's button in the top bar, or its item in one of the top bar's menus, brought into view. */
async function reach(page: Page, name: string): Promise<boolean> {
  const bar = page.locator('.kf-topbar');
  const direct = bar.getByRole('button', { name, exact: true });
  if ((await direct.count()) === 1 && (await inView(page, direct))) return true;
  const menus = bar.locator('[aria-haspopup="menu"]');
  for (let i = 0; i < (await menus.count()); i++) {
    await menus.nth(i).click();
    const item = page.getByRole('menuitem', {
      name: new RegExp(`^${name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}`),
    });
    const found = (await item.count()) === 1;
    if (found) await item.scrollIntoViewIfNeeded();
    const ok = found && (await inView(page, item));
    await page.keyboard.press('Escape');
    if (ok) return true;
  }
  return false;
}

describe.each([
  ['phone', 390, 844],
  ['tablet', 768, 1024],
])('%s %i×%i', (device, width, height) => {
  let app: ServedApp;
  let page: Page;
  const problems: string[] = [];
  beforeAll(async () => {
    mkdirSync(shots, { recursive: true });
    app = await serveDevApp();
    page = await (await app.newContext({ width, height })).newPage();
    page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    await page.goto(app.url);
    await page.locator('.kf-topbar').waitFor();
  });
  afterAll(() => app?.close());

  it('keeps the top bar inside the window and every command reachable', async () => {
    const overflow = await page.evaluate(() => {
      const bar = document.querySelector('.kf-topbar')!;
      return [...bar.querySelectorAll('button, input')]
        .filter((el) => el.getBoundingClientRect().right > window.innerWidth + 0.5)
        .map((el) => el.textContent || el.getAttribute('aria-label'));
    });
    expect(overflow).toEqual([]);
    const missing: string[] = [];
    for (const name of COMMANDS) if (!(await reach(page, name))) missing.push(name);
    expect(missing).toEqual([]);
  });

  it('shows the picture in view', async () => {
    const canvas = page
      .getByRole('img', { name: 'Rendered picture' })
      .or(page.locator('canvas.kf-render__canvas'));
    await canvas.first().waitFor();
    expect(await inView(page, canvas.first())).toBe(true);
    const box = (await canvas.first().boundingBox())!;
    expect(box.width * box.height).toBeGreaterThan(0.15 * width * height);
  });

  it('runs commands from where they are: Help opens, Play becomes Pause', async () => {
    const open = async (name: string) => {
      const direct = page.locator('.kf-topbar').getByRole('button', { name, exact: true });
      if ((await direct.count()) === 1 && (await direct.isVisible())) return direct.click();
      await page.getByRole('button', { name: 'Menu' }).click();
      await page.getByRole('menuitem', { name: new RegExp(`^${name}`) }).click();
    };
    // Every example is one tap away in the gallery, which fits the screen.
    await open('Examples');
    const gallery = page.getByRole('dialog', { name: 'Examples' });
    await gallery.waitFor();
    expect(await gallery.locator('.kf-gallery__card').count()).toBe(EXAMPLE_TITLES.length);
    expect((await gallery.boundingBox())!.width).toBeLessThanOrEqual(width);
    await page.keyboard.press('Escape');
    await gallery.waitFor({ state: 'detached' });
    await open('Help');
    await page.getByRole('dialog', { name: 'Help' }).waitFor();
    await page.keyboard.press('Escape');
    await page.getByRole('dialog', { name: 'Help' }).waitFor({ state: 'detached' });
    await open('Play animation');
    expect(await reach(page, 'Pause animation')).toBe(true);
    await open('Pause animation');
  });

  it('fits the presentation: step bar, step list and note inside the width', async () => {
    await page.screenshot({ path: join(shots, `${device}-editor.png`) });
    await page.locator('.kf-topbar').getByRole('button', { name: 'Present' }).click();
    await page.getByTestId('present-mode').waitFor();
    const bar = page.getByRole('navigation', { name: 'Construction steps' });
    expect(await inView(page, bar)).toBe(true);
    for (const name of ['First step', 'Previous step', 'Next step', 'Last step'])
      expect(await inView(page, bar.getByRole('button', { name }))).toBe(true);
    const toggle = page.getByRole('button', { name: 'Steps' });
    // Listed from the start where there is room; behind the Steps button on a phone.
    expect(await toggle.getAttribute('aria-pressed')).toBe(String(device !== 'phone'));
    if (device === 'phone') await toggle.click();
    const list = page.getByRole('navigation', { name: 'Step list' });
    expect(await inView(page, list)).toBe(true);
    await list.getByRole('button').nth(1).click();
    expect(await page.getByTestId('step-now').textContent()).toMatch(/^Step 2 \//);
    if (device === 'phone') expect(await list.count()).toBe(0); // picking a step uncovers the picture
    await page.keyboard.press('End');
    // The whole construction shows the picture (the canvas fades in), in view under the panels.
    const canvas = page.locator('canvas.kf-render__canvas');
    await expect
      .poll(() => canvas.evaluate((c) => getComputedStyle(c).opacity), { timeout: 30_000 })
      .toBe('1');
    expect(await inView(page, canvas)).toBe(true);
    await page.waitForTimeout(device === 'phone' ? 2_000 : 0); // a first frame for the screenshot
    await page.screenshot({ path: join(shots, `${device}-present.png`) });
    await page.keyboard.press('Escape');
    await page.locator('.kf-topbar').waitFor();
  }, 60_000);

  it.runIf(device === 'phone')('shows one pane at a time: Graph, Picture and Inspector tabs', async () => {
    const tabs = page.getByRole('tablist', { name: 'Panes' });
    expect(await tabs.getByRole('tab', { name: 'Picture' }).getAttribute('aria-selected')).toBe('true');
    expect(await page.locator('.react-flow').count()).toBe(0);
    await tabs.getByRole('tab', { name: 'Graph' }).click();
    await page.locator('.react-flow__node').first().waitFor();
    expect(await inView(page, page.locator('.react-flow'))).toBe(true);
    expect(await page.getByTestId('render-pane').count()).toBe(0);
    await page.locator('.react-flow__node').first().click();
    await page.screenshot({ path: join(shots, 'phone-graph.png') });
    await tabs.getByRole('tab', { name: 'Inspector' }).click();
    const inspector = page.getByRole('complementary', { name: /Inspector/ });
    await inspector.first().waitFor();
    expect(await inView(page, inspector.first())).toBe(true);
    await page.screenshot({ path: join(shots, 'phone-inspector.png') });
    await tabs.getByRole('tab', { name: 'Picture' }).click();
    await page.getByTestId('render-pane').waitFor();
  });

  it("fits the first visit's welcome card, every choice inside the window", async () => {
    const first = await (await app.newContext({ width, height }, { firstVisit: true })).newPage();
    await first.goto(app.url);
    const card = first.getByRole('region', { name: 'Welcome to Kleinflow' });
    await card.waitFor();
    const buttons = card.getByRole('button');
    for (let i = 0; i < (await buttons.count()); i++)
      expect(await inView(first, buttons.nth(i)), (await buttons.nth(i).textContent()) ?? '').toBe(true);
    await first.close();
  });

  it('no console errors', () => {
    expect(problems).toEqual([]);
  });
});
