/**
 * The Help's 3D quick start (src/app/help/quick-start.ts QUICK_START_3D) followed as a newcomer
 * would, in real Chromium: from New, the palette finds Render 3D and Sphairahedron by the words the
 * steps use, the two wires the steps name give a quasi-sphere, and the view moves as step 4 says
 * (scroll zooms, drag orbits, F resets, the inversion centre's handle reshapes it without a
 * recompile). The render pane is small (view-3d-page.ts): SwiftShader sphere-traces slowly.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { QUICK_START_3D } from '../../src/app/help/quick-start.ts';
import { appSessionForSuite } from './app-suite.ts';
import { addNode, connect, nodeCount, nodeEl, renderPixels, waitRendered } from './editor-page.ts';
import { freePanePoint, openSmall3dPane } from './view-3d-page.ts';

let page: Page;
appSessionForSuite((s) => ({ page } = s), { open: openSmall3dPane });

const camera = () => page.evaluate(() => window.__kleinflow!.store.getState().doc.camera3d);
const stats = () => page.evaluate(() => window.__kleinflow!.viewport!.stats);

describe('the 3D quick start', () => {
  it('says what this test does, word for word', () => {
    const text = QUICK_START_3D.map((s) => s.detail).join(' ');
    for (const words of [
      '“render 3d”',
      '“sphairahedron”',
      '“elements”',
      '“seed”',
      '“seeds”',
      'Scroll',
      'drag',
    ])
      expect(text).toContain(words);
  });

  it('gives a quasi-sphere from New in four steps, and the view and the handle move it', async () => {
    // Step 1: New, then the Sphairahedron from the palette.
    await page.getByRole('button', { name: 'New' }).click();
    await expect.poll(() => nodeCount(page)).toBe(0);
    const sph = await addNode(page, 'sphairahedron', 60, 40);
    expect(await nodeEl(page, sph).textContent()).toContain('Sphairahedron');
    // Step 2: Render 3D.
    const render = await addNode(page, 'render 3d', 330, 40);
    expect(await nodeEl(page, render).textContent()).toContain('Render 3D');
    // Step 3: the two wires the step names.
    await connect(page, sph, 'elements', render, 'elements');
    await connect(page, sph, 'seed', render, 'seeds');
    await expect
      .poll(() => page.evaluate(() => window.__kleinflow!.store.getState().doc.edges.length))
      .toBe(2);
    await waitRendered(page, 240_000);
    expect(await page.getByTestId('diagnostics-count').textContent()).toMatch(/No problems/);
    const drawn = await renderPixels(page);
    expect(drawn.sd).toBeGreaterThan(10); // a picture, not the flat background
    const compiles = (await stats()).compiles;

    // Step 4: scroll zooms, drag orbits, F resets (to the node's camera: no camera3d).
    const pane = await freePanePoint(page);
    await page.mouse.move(pane.x, pane.y);
    await page.mouse.wheel(0, -240);
    await expect.poll(camera, { timeout: 90_000 }).toBeTruthy();
    const zoomed = (await camera())!;
    const from = await freePanePoint(page);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(from.x + 40, from.y + 10, { steps: 5 });
    await page.mouse.up();
    await expect
      .poll(async () => JSON.stringify(await camera()), { timeout: 90_000 })
      .not.toBe(JSON.stringify(zoomed));
    await page.getByTestId('render-pane').focus();
    await page.keyboard.press('f');
    await expect.poll(camera, { timeout: 90_000 }).toBeUndefined();

    // … and the inversion sphere's centre handle reshapes it, with no recompile.
    const centreParam = () =>
      page.evaluate(
        (id) => window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === id)!.params.center,
        sph,
      );
    const before = await centreParam();
    const knob = page.locator(`[data-handle="${sph}/center"]`);
    const k = (await knob.boundingBox())!;
    await page.mouse.move(k.x + k.width / 2, k.y + k.height / 2);
    await page.mouse.down();
    await page.mouse.move(k.x + k.width / 2 + 12, k.y + k.height / 2 + 6, { steps: 4 });
    await page.mouse.up();
    await expect.poll(centreParam, { timeout: 90_000 }).not.toEqual(before);
    expect((await stats()).compiles).toBe(compiles);
  }, 600_000);
});
