/**
 * The sphairahedron parameter-space view in the render pane (paper Fig. 30), as a person uses it,
 * at 1280×720 and at a phone's 390×844: the pane's switch shows it beside the 3D graph, it names
 * the class at the current (zb, zc) (here tunnels, Fig. 32's parameter), a click sets (zb, zc) in
 * one undo step, a drag pans and leaves the parameter alone, the arrow keys step it, and axe-core
 * finds no serious violation. The page runs with `?test` (window.__kleinflow).
 * docs/math-3d.md "The parameter-space view".
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import type { ServedApp } from './app-server.ts';
import { servedAppForSuite } from './app-suite.ts';
import { audit, readable } from './axe-audit.ts';

/** A sphairahedron at Fig. 32's tunnels, a Render 3D node and the parameter-space view. */
const DOC = {
  format: 'kleinflow',
  version: 1,
  meta: { title: 'parameter space' },
  nodes: [
    {
      id: 'sph',
      type: 'sphairahedron',
      version: 2,
      position: [0, 0],
      params: { shape: 'cube-a', zb: -1.35, zc: -0.3, center: [0, 0, 1.64], radius: 2.07 },
    },
    { id: 'render', type: 'render-3d', position: [360, 0], params: { maxIterations: 20, marchSteps: 200 } },
    { id: 'space', type: 'sphairahedron-space', position: [360, 300], params: {} },
  ],
  edges: [
    { id: 'e1', from: { node: 'sph', port: 'elements' }, to: { node: 'render', port: 'elements' } },
    { id: 'e2', from: { node: 'sph', port: 'seed' }, to: { node: 'render', port: 'seeds' } },
    { id: 'e3', from: { node: 'sph', port: 'elements' }, to: { node: 'space', port: 'sphairahedron' } },
  ],
  view: { center: [0, 0], scale: 4 },
};

const SCREENSHOT = 'examples/screenshots/sphairahedron-space.png';
let app: ServedApp;
servedAppForSuite((served) => {
  app = served;
});

async function open(width: number, height: number): Promise<Page> {
  const page = await (await app.newContext({ width, height })).newPage();
  page.setDefaultTimeout(60_000);
  await page.goto(`${app.url}?test`);
  await page.waitForFunction(() => window.__kleinflow?.store);
  await page.evaluate(
    (d) => window.__kleinflow!.store.dispatch({ type: 'load-document', doc: d as never }),
    DOC,
  );
  return page;
}

const params = (page: Page) =>
  page.evaluate(() => {
    const p = window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === 'sph')!.params;
    return [Number(p.zb), Number(p.zc)];
  });
const status = (page: Page) => page.getByTestId('space-view-status').textContent();
const slider = (page: Page) => page.getByRole('slider', { name: /Parameter space of cube A/ });

/** Shows the view by the pane's switch (the phone shows the Picture tab first, if it has tabs). */
async function showSpace(page: Page) {
  const picture = page.getByRole('tab', { name: 'Picture' });
  if (await picture.count()) await picture.click();
  const button = page.getByRole('button', { name: 'Parameter space', exact: true });
  await button.click();
  await expect.poll(() => button.getAttribute('aria-pressed')).toBe('true');
  await page.getByTestId('space-view').and(page.locator('[data-done="yes"]')).waitFor({ timeout: 120_000 });
}

/** Clicks the view where (zb, zc) is, in its first window (centre (0, 0), height 5). */
async function clickAt(page: Page, zb: number, zc: number) {
  const box = (await slider(page).boundingBox())!;
  const x = box.width / 2 + (zb / 5) * box.height;
  const y = box.height / 2 - (zc / 5) * box.height;
  await slider(page).click({ position: { x, y } });
}

describe.each([
  ['desktop', 1280, 720],
  ['phone', 390, 844],
] as const)('sphairahedron parameter space, %s %i×%i', (device, width, height) => {
  it('switches to the view, names the class, sets (zb, zc) on a click (one undo step), pans, steps with the keys', async () => {
    const page = await open(width, height);
    await showSpace(page);
    await expect.poll(() => status(page)).toContain('tunnels');
    await expect(slider(page).getAttribute('aria-valuetext')).resolves.toMatch(/tunnels/);

    await clickAt(page, 0.8, 0.3);
    await expect.poll(() => params(page)).not.toEqual([-1.35, -0.3]);
    const [zb, zc] = await params(page);
    expect(Math.abs(zb! - 0.8)).toBeLessThan(0.06);
    expect(Math.abs(zc! - 0.3)).toBeLessThan(0.06);
    await expect.poll(() => status(page)).toContain('valid');
    await expect(slider(page).getAttribute('aria-valuetext')).resolves.toMatch(/valid/);
    // The README's picture of the view, the red point in the valid region.
    if (device === 'desktop') {
      await page.getByTestId('space-view').and(page.locator('[data-done="yes"]')).waitFor();
      await page.getByTestId('render-pane').screenshot({ path: SCREENSHOT });
    }

    // A drag pans the view (its shown zb range changes); the parameter stays.
    const before = await slider(page).getAttribute('aria-valuemin');
    const box = (await slider(page).boundingBox())!;
    await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.6);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++)
      await page.mouse.move(box.x + box.width * 0.3 + 8 * i, box.y + box.height * 0.6);
    await page.mouse.up();
    await expect.poll(() => slider(page).getAttribute('aria-valuemin')).not.toBe(before);
    expect(await params(page)).toEqual([zb, zc]);

    // The arrow keys step zb and zc, each one step; the focus is visible.
    await slider(page).focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => (await params(page))[0]).toBeCloseTo(zb! + 0.05, 5);
    await page.keyboard.press('ArrowUp');
    await expect.poll(async () => (await params(page))[1]).toBeCloseTo(zc! + 0.05, 5);
    const outline = await slider(page).evaluate((el) => getComputedStyle(el).outlineStyle);
    expect(outline).not.toBe('none');

    const violations = readable(await audit(page));
    expect(violations, violations).toBe('');

    // Three undos: the two key steps, then the click.
    for (let i = 0; i < 3; i++) await page.evaluate(() => window.__kleinflow!.store.undo());
    await expect.poll(() => params(page)).toEqual([-1.35, -0.3]);

    // Back to the 3D picture: the view is gone, the switch says so.
    await page.getByRole('button', { name: '3D picture' }).click();
    await expect.poll(() => page.getByTestId('space-view').count()).toBe(0);
    await page.context().close();
  }, 300_000);
});

describe('sphairahedron parameter space, side by side on a wide screen (1600×720)', () => {
  it('shows the view beside the 3D picture by default, a click there moves the 3D graph’s parameter', async () => {
    const page = await open(1600, 720);
    const pane = page.getByTestId('render-pane');
    // At first the editor takes most of the width and the view takes turns with the 3D picture;
    // widening the render pane with the divider's keys (as a keyboard user would) makes room.
    const sideBySide = page.getByRole('button', { name: 'Side by side', exact: true });
    expect(await sideBySide.count()).toBe(0);
    await page.getByRole('separator', { name: 'Resize panes' }).focus();
    for (let i = 0; i < 40 && ((await pane.boundingBox())?.width ?? 0) < 960; i++)
      await page.keyboard.press('ArrowLeft');
    const paneBox = (await pane.boundingBox())!;
    expect(paneBox.width).toBeGreaterThanOrEqual(900);
    // Wide enough: the switch offers "Side by side", and it is what the pane shows.
    const both = sideBySide;
    await expect.poll(() => both.getAttribute('aria-pressed')).toBe('true');
    const view = page.getByTestId('space-view');
    await view.and(page.locator('[data-done="yes"]')).waitFor({ timeout: 120_000 });
    await expect.poll(() => status(page)).toContain('tunnels');
    // The view takes the right half; the 3D picture's canvas and its handles stay on the left.
    const viewBox = (await view.boundingBox())!;
    expect(viewBox.x).toBeGreaterThanOrEqual(paneBox.x + paneBox.width * 0.45);
    expect(viewBox.x + viewBox.width).toBeLessThanOrEqual(paneBox.x + paneBox.width + 1);
    // The 3D picture is the left half: its canvas and overlay end where the view begins, so no part
    // of the picture or its handles is hidden under the view.
    const canvasBox = (await page.locator('canvas[aria-label="Rendered picture"]').boundingBox())!;
    const overlayBox = (await page.getByRole('group', { name: /3D construction overlay/ }).boundingBox())!;
    for (const box of [canvasBox, overlayBox]) {
      expect(box.x).toBeLessThanOrEqual(paneBox.x + 1);
      expect(box.x + box.width).toBeLessThanOrEqual(viewBox.x + 1);
      expect(box.width).toBeGreaterThan(paneBox.width * 0.45);
    }
    const reset = (await page.getByRole('button', { name: 'Reset view' }).boundingBox())!;
    expect(reset.x + reset.width).toBeLessThanOrEqual(viewBox.x);
    await clickAt(page, 0.8, 0.3);
    await expect.poll(() => status(page)).toContain('valid');
    const [zb, zc] = await params(page);
    expect(Math.abs(zb! - 0.8)).toBeLessThan(0.06);
    expect(Math.abs(zc! - 0.3)).toBeLessThan(0.06);
    // Both stay on screen: still side by side after the edit.
    expect(await both.getAttribute('aria-pressed')).toBe('true');
    const violations = readable(await audit(page));
    expect(violations, violations).toBe('');
    await pane.screenshot({ path: 'examples/screenshots/sphairahedron-space-side-by-side.png' });
    await page.context().close();
  }, 300_000);
});
