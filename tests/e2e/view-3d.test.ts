/**
 * The 3D view as a person meets it: a 3D example opens as a picture with its wireframe overlay
 * and "Reset view"; dragging orbits, the wheel zooms, Reset view comes back; a sphere's centre
 * handle drags and an inspector edit redraws without compiling anything; the camera is saved with
 * the document; the PNG export draws the 3D view; switching to a 2D example and back just works;
 * and on a 390 × 844 phone the picture is there. Compile counts come from the test hooks (`?test`).
 *
 * SwiftShader sphere-traces slowly (seconds a frame even in a small pane), so the pane is small and,
 * once the example is open, its render node is made cheaper — one sample, no occlusion or shadow,
 * fewer iterations and march steps: values only, the program stays the same.
 */
import { mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { beforeAll, describe, expect, it } from 'vitest';
import { LIMITS } from '../../nodes/core/limits.ts';
import { DEFAULT_LIGHTING_3D } from '../../nodes/core/scene-3d.ts';
import { decodePng } from '../../src/io/png.ts';
import { repoRoot, type ServedApp } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';
import { renderPixels, thumbDiff, waitRendered } from './editor-page.ts';
import { menu } from './io-page.ts';
import { freePanePoint, openSmall3dPane } from './view-3d-page.ts';

const FIG11 = 'Fig. 11 — the orbit of a seed sphere under six sphere inversions';
const FIG237 = '(2,3,7) hyperbolic tessellation';
const shots = join(repoRoot, 'test-artifacts');

let app: ServedApp;
let page: Page;

type Vec3 = [number, number, number];
interface Camera {
  position: Vec3;
  target: Vec3;
  fovDeg: number;
}

const docCamera = (p: Page = page) =>
  p.evaluate(() => window.__kleinflow!.store.getState().doc.camera3d as Camera | undefined);
const compiles = (p: Page = page) => p.evaluate(() => window.__kleinflow!.viewport!.stats.compiles);
const seedParams = () =>
  page.evaluate(
    () =>
      window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === 'seed')!.params as Record<
        string,
        unknown
      >,
  );
/** Polls wait this long: a SwiftShader frame blocks the page for seconds. */
const SLOW = { timeout: 90_000 };

/** The render node's cost settings for SwiftShader (values, never a recompile). */
const CHEAP = { samples: 1, occlusion: 0, shadow: 0, maxIterations: 10, marchSteps: 48, deScale: 1 };
/**
 * A full-size frame SwiftShader draws in many bands: the example's shading, and march steps of a
 * twentieth of the bound (the tracer is fast enough that the example's own cost finishes a small
 * pane's sample before a screenshot can catch it half drawn).
 */
const DEAR = {
  samples: 1,
  occlusion: DEFAULT_LIGHTING_3D.occlusion,
  shadow: DEFAULT_LIGHTING_3D.shadow,
  maxIterations: 30,
  marchSteps: LIMITS.maxMarchSteps,
  deScale: 0.05,
};
const cheapen = (p: Page = page, params: Record<string, number> = CHEAP) =>
  p.evaluate(
    (params) =>
      window.__kleinflow!.store.dispatchSilently({
        type: 'set-params',
        patches: [{ nodeId: 'render', params }],
      }),
    params,
  );
const paneStats = () => page.evaluate(() => window.__kleinflow!.viewport!.stats);
interface Shot {
  readonly width: number;
  readonly height: number;
  readonly data: number[];
}
/** The render pane as shown on screen, RGBA (the screenshot is decoded by the browser). */
async function paneShot(): Promise<Shot> {
  const png = await page.getByTestId('render-pane').screenshot();
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    [c.width, c.height] = [img.width, img.height];
    const g = c.getContext('2d')!;
    g.drawImage(img, 0, 0);
    return { width: c.width, height: c.height, data: [...g.getImageData(0, 0, c.width, c.height).data] };
  }, png.toString('base64'));
}

/** Mean absolute RGB difference of two same-sized images over rows [from, to) given as fractions of the height. */
function rowsDiff(a: Shot, b: Shot, from: number, to: number) {
  const [y0, y1] = [Math.ceil(from * a.height), Math.floor(to * a.height)];
  let sum = 0;
  for (let i = y0 * a.width * 4; i < y1 * a.width * 4; i++)
    if (i % 4 !== 3) sum += Math.abs(a.data[i] - b.data[i]);
  return sum / Math.max(1, (y1 - y0) * a.width * 3);
}

const distance = (c: Camera) => Math.hypot(...c.position.map((v, i) => v - c.target[i]));

async function openExample(p: Page, title: string) {
  await p.getByRole('button', { name: 'Examples' }).click();
  const gallery = p.getByRole('dialog', { name: 'Examples' });
  await gallery.getByRole('searchbox').fill(title.slice(0, 24));
  await gallery.locator('.kf-gallery__card').filter({ hasText: title }).first().click();
  await gallery.waitFor({ state: 'detached' });
  await expect.poll(() => p.getByLabel('Document title').inputValue(), SLOW).toBe(title);
}

/** A point of the render pane at fractions (fx, fy) of its size. */
async function paneAt(fx: number, fy: number) {
  const b = (await page.getByTestId('render-pane').boundingBox())!;
  return { x: b.x + fx * b.width, y: b.y + fy * b.height };
}

async function dragMouse(from: { x: number; y: number }, dx: number, dy: number) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x + dx, from.y + dy, { steps: 3 });
  await page.mouse.up();
}

beforeAll(() => mkdirSync(shots, { recursive: true }));
appSessionForSuite((s) => ({ app, page } = s), { open: openSmall3dPane });

describe('3D view', () => {
  let initial: Awaited<ReturnType<typeof renderPixels>>;

  it('opens a 3D example as a picture with its wireframes, handles and Reset view (no Fit)', async () => {
    await openExample(page, FIG11);
    await waitRendered(page, 120_000);
    await cheapen();
    await expect.poll(() => page.evaluate(() => window.__kleinflow!.viewport!.stats.samples), SLOW).toBe(1);
    await page.getByRole('button', { name: 'Reset view' }).waitFor();
    expect(await page.getByRole('button', { name: 'Fit', exact: true }).count()).toBe(0);
    expect(await page.getByRole('group', { name: /3D construction overlay/ }).count()).toBe(1);
    expect(await page.locator('[data-handle="seed/center"]').count()).toBe(1);
    initial = await renderPixels(page);
    expect(initial.sd).toBeGreaterThan(8); // a picture, not a flat background
    await page.screenshot({ path: join(shots, 'view-3d-desktop.png') });
  }, 180_000);

  it('a slow full-size picture appears band by band over the preview, its progress in the status bar', async () => {
    await cheapen(page, DEAR);
    await waitRendered(page, 120_000);
    const progress = page.getByTestId('render-progress');
    // A partial picture: some bands shown, the sample not whole before or after the screenshot. The
    // sample may win the race with the screenshot on a fast machine: then orbit and try again.
    let partial: { shot: Shot; done: number; left: number } | null = null;
    for (let attempt = 0; attempt < 8 && !partial; attempt++) {
      await dragMouse(await freePanePoint(page), 20, 8);
      await page.waitForFunction(() => {
        const s = window.__kleinflow!.viewport!.stats;
        return s.samples === 0 && s.band !== null && s.band.rows >= 0.1 * s.band.of;
      }, SLOW);
      const text = await progress.textContent();
      const before = (await paneStats()).band;
      const shot = await paneShot();
      const after = await paneStats();
      if (!before || !after.band || after.samples > 0 || after.band.rows > 0.9 * after.band.of) continue;
      expect(text).toMatch(/^Full size: \d+ % …/);
      expect(await page.getByTestId('render-announcement').textContent()).toMatch(/full size/);
      partial = { shot, done: before.rows / before.of, left: after.band.rows / after.band.of };
    }
    expect(partial).not.toBeNull();
    const { shot, done, left } = partial!;
    await waitRendered(page, 120_000);
    expect((await paneStats()).bands).toBeGreaterThan(1);
    expect(await page.getByTestId('render-announcement').textContent()).toMatch(/drawn/);
    const whole = await paneShot();
    // The rows drawn by the screenshot are the full-size picture's; those not yet drawn, the
    // upscaled preview's, which differ.
    const top = rowsDiff(shot, whole, 0, done - 0.02);
    const bottom = rowsDiff(shot, whole, left + 0.02, 1);
    expect(top).toBeLessThan(1);
    expect(bottom).toBeGreaterThan(Math.max(2, 4 * top));
    await cheapen();
    await waitRendered(page, 120_000);
  }, 360_000);

  it('dragging orbits the camera: the picture changes, the camera is stored, nothing compiles', async () => {
    const before = await compiles();
    await dragMouse(await freePanePoint(page), 60, 25);
    await expect.poll(() => docCamera(), SLOW).toBeDefined();
    await waitRendered(page, 120_000);
    expect(thumbDiff(await renderPixels(page), initial)).toBeGreaterThan(3);
    const camera = (await docCamera())!;
    expect(camera.target).toEqual([0, 0, 0]);
    expect(await compiles()).toBe(before);
  }, 180_000);

  it('the wheel zooms in; Reset view goes back to the render node’s camera and picture', async () => {
    const orbited = (await docCamera())!;
    const centre = await paneAt(0.5, 0.5);
    await page.mouse.move(centre.x, centre.y);
    await page.mouse.wheel(0, -300);
    await expect.poll(async () => distance((await docCamera())!), SLOW).toBeLessThan(distance(orbited) * 0.8);
    await page.getByRole('button', { name: 'Reset view' }).click();
    await expect.poll(() => docCamera(), SLOW).toBeUndefined();
    // Wait for the picture itself: the status may still say "rendered" for the zoomed camera
    // before the reset reaches the pane on a loaded machine.
    await expect
      .poll(async () => thumbDiff(await renderPixels(page), initial), { timeout: 120_000, interval: 500 })
      .toBeLessThan(1);
  }, 180_000);

  it('dragging the seed sphere’s centre handle moves the node without compiling; undo puts it back', async () => {
    const before = await compiles();
    const h = (await page.locator('[data-handle="seed/center"]').boundingBox())!;
    await dragMouse({ x: h.x + h.width / 2, y: h.y + h.height / 2 }, 25, -15);
    await expect.poll(async () => (await seedParams()).center, SLOW).not.toEqual([0, 0, 0]);
    expect(await docCamera()).toBeUndefined(); // a handle drag is not an orbit
    await waitRendered(page, 120_000);
    expect(await compiles()).toBe(before);
    await page.locator('.kf-graph').click({ position: { x: 10, y: 10 } });
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await seedParams()).center, SLOW).toEqual([0, 0, 0]);
  }, 180_000);

  it('the keyboard moves the seed’s centre handle: Tab reaches it by name, arrows and Page Up move it', async () => {
    const knob = page.locator('[data-handle="seed/center"]');
    expect(await knob.getAttribute('aria-label')).toMatch(/center at 0, 0, 0: arrow keys move it/);
    await knob.focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => (await seedParams()).center, SLOW).not.toEqual([0, 0, 0]);
    const across = (await seedParams()).center as number[];
    await knob.focus();
    await page.keyboard.press('PageUp');
    await expect.poll(async () => (await seedParams()).center, SLOW).not.toEqual(across);
    expect(await docCamera()).toBeUndefined(); // the keys moved the handle, not the camera
    // Two presses, two undo steps.
    await page.locator('.kf-graph').click({ position: { x: 10, y: 10 } });
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await seedParams()).center, SLOW).toEqual(across);
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await seedParams()).center, SLOW).toEqual([0, 0, 0]);
  }, 180_000);

  it('an inspector edit of the seed’s radius redraws without compiling', async () => {
    const before = await compiles();
    const picture = await renderPixels(page);
    // The seed node is below the fold of this small graph pane: select it through the store.
    await page.evaluate(() => window.__kleinflow!.store.setSelection(['seed']));
    const inspector = page.getByRole('complementary', { name: 'Inspector' });
    if ((await inspector.count()) === 0) await page.getByRole('button', { name: 'Inspector' }).click();
    const radius = inspector.getByLabel('radius', { exact: true });
    await radius.fill('0.2');
    await radius.press('Enter');
    await expect.poll(async () => (await seedParams()).radius, SLOW).toBe(0.2);
    await waitRendered(page, 120_000);
    expect(thumbDiff(await renderPixels(page), picture)).toBeGreaterThan(0.5);
    expect(await compiles()).toBe(before);
  }, 180_000);

  it('exports the 3D view as a PNG of the asked size', async () => {
    await menu(page, 'Export', 'PNG image');
    const dialog = page.getByRole('dialog', { name: 'Export PNG' });
    await dialog.getByLabel('Width in pixels').fill('160');
    await dialog.getByLabel('Height in pixels').fill('120');
    await dialog.getByLabel('Samples').fill('2');
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 120_000 }),
      dialog.getByRole('button', { name: /^Export 160/ }).click(),
    ]);
    const image = decodePng(new Uint8Array(readFileSync((await download.path())!)));
    expect([image.width, image.height]).toEqual([160, 120]);
    // The seed sphere is in the middle: the centre differs from the corner (the background).
    const at = (x: number, y: number) => [...image.data.slice((y * 160 + x) * 4, (y * 160 + x) * 4 + 3)];
    const [c, k] = [at(80, 60), at(2, 2)];
    expect(Math.abs(c[0] - k[0]) + Math.abs(c[1] - k[1]) + Math.abs(c[2] - k[2])).toBeGreaterThan(30);
    await dialog.waitFor({ state: 'detached' }).catch(() => page.keyboard.press('Escape'));
  }, 180_000);

  it('the orbited camera is saved with the document and comes back on reload', async () => {
    await dragMouse(await freePanePoint(page), -50, 20);
    await expect.poll(() => docCamera(), SLOW).toBeDefined();
    await page.waitForTimeout(1500); // the last move settles into the document, and autosave runs
    const saved = (await docCamera())!;
    await page.reload();
    await page.getByRole('button', { name: 'Reset view' }).waitFor();
    expect(await docCamera()).toEqual(saved);
    await waitRendered(page, 120_000);
  }, 180_000);

  it('editing the camera on the Render 3D node brings the view to it (the orbited camera is dropped)', async () => {
    expect(await docCamera()).toBeDefined();
    const s1 = async () => (await page.locator('[data-handle="s1/center"]').boundingBox())!;
    const before = await s1();
    await page.evaluate(() =>
      window.__kleinflow!.store.dispatch({
        type: 'set-params',
        patches: [{ nodeId: 'render', params: { camera: [2.4, 1.2, 1.6] } }],
      }),
    );
    await expect.poll(() => docCamera(), SLOW).toBeUndefined();
    const after = await s1();
    expect(Math.hypot(after.x - before.x, after.y - before.y)).toBeGreaterThan(5);
    await waitRendered(page, 120_000);
  }, 180_000);

  it('switching to a 2D example and back: Fit and pan/zoom there, Reset view and orbit here', async () => {
    await openExample(page, FIG237);
    await page.getByRole('button', { name: 'Fit', exact: true }).waitFor();
    expect(await page.getByRole('button', { name: 'Reset view' }).count()).toBe(0);
    await waitRendered(page, 120_000);
    expect((await renderPixels(page)).sd).toBeGreaterThan(8);
    // Back: undo brings the 3D graph back (as it was, cheap settings and all).
    await page.locator('.kf-graph').click({ position: { x: 10, y: 10 } });
    await page.keyboard.press('Control+z');
    await expect.poll(() => page.getByLabel('Document title').inputValue(), SLOW).toBe(FIG11);
    await page.getByRole('button', { name: 'Reset view' }).waitFor();
    await waitRendered(page, 120_000);
    expect((await renderPixels(page)).sd).toBeGreaterThan(8);
  }, 240_000);
});

describe('3D view on a phone', () => {
  it('390 × 844: the 3D example’s picture is in view', async () => {
    const phone = await (await app.newContext({ width: 390, height: 844 })).newPage();
    phone.setDefaultTimeout(150_000);
    await phone.goto(`${app.url}?test`);
    await phone.getByRole('tab', { name: 'Picture' }).waitFor();
    // The example as the gallery opens it, with the cheap settings already in (a full-quality
    // first frame of a 390 × 700 pane takes minutes in SwiftShader).
    const doc = JSON.parse(
      readFileSync(join(repoRoot, 'examples/3d/fig11-sphere-inversion-fractal.kleinflow.json'), 'utf8'),
    );
    const render = doc.nodes.find((n: { id: string }) => n.id === 'render');
    render.params = { ...render.params, ...CHEAP };
    await phone.evaluate((d) => window.__kleinflow!.store.dispatch({ type: 'load-document', doc: d }), doc);
    await waitRendered(phone, 120_000);
    const pane = (await phone.getByTestId('render-pane').boundingBox())!;
    expect(pane.width).toBeGreaterThan(300);
    expect(pane.height).toBeGreaterThan(300);
    expect((await renderPixels(phone)).sd).toBeGreaterThan(8);
    await phone.screenshot({ path: join(shots, 'view-3d-phone.png') });
    await phone.close();
  }, 180_000);
});
