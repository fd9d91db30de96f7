/**
 * The sphairahedron's parameter space in the inspector (paper Fig. 30), as a person uses it: the
 * panel names the class at the current (zb, zc) (here tunnels, Fig. 32's parameter), a click sets
 * (zb, zc) in one undo step, a drag pans the panel and leaves the parameter alone, the arrow keys
 * step it. The page runs with `?test` (window.__kleinflow).
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { appSessionForSuite, inspectorOn } from './app-suite.ts';

/** One sphairahedron node (no render node: the panel is the inspector's, not the picture's). */
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
  ],
  edges: [],
  view: { center: [0, 0], scale: 4 },
};

const SCREENSHOT = 'examples/screenshots/sphairahedron-space.png';
let page: Page;
appSessionForSuite((s) => ({ page } = s), { query: '?test', ready: inspectorOn(DOC, 'sph') });

const inspector = () => page.getByRole('complementary', { name: 'Inspector' });
const params = () =>
  page.evaluate(() => {
    const p = window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === 'sph')!.params;
    return [Number(p.zb), Number(p.zc)];
  });
const status = () => inspector().getByTestId('sphairahedron-space-status').textContent();

describe('sphairahedron parameter space', () => {
  it('names the class, sets (zb, zc) on a click (one undo step), pans on a drag, steps with the keys', async () => {
    const panel = inspector().getByRole('slider', { name: /Parameter space of cube A/ });
    await panel.waitFor();
    await expect.poll(status).toContain('tunnels');
    // The README's picture of the panel (Fig. 30's small panel), at Fig. 32's parameter.
    await panel.scrollIntoViewIfNeeded();
    await inspector().screenshot({ path: SCREENSHOT });
    await panel.scrollIntoViewIfNeeded();
    const box = (await panel.boundingBox())!;
    // The panel shows zb, zc ∈ [−2.5, 2.5]: (0.8, 0.3) is a valid cube A.
    const at = { x: ((0.8 + 2.5) / 5) * box.width, y: ((2.5 - 0.3) / 5) * box.height };
    await panel.click({ position: at });
    await expect.poll(params).not.toEqual([-1.35, -0.3]);
    const [zb, zc] = await params();
    expect(Math.abs(zb - 0.8)).toBeLessThan(0.05);
    expect(Math.abs(zc - 0.3)).toBeLessThan(0.05);
    await expect.poll(status).toContain('valid');
    await expect(panel.getAttribute('aria-valuetext')).resolves.toMatch(/valid/);

    // A drag pans the panel (its shown range changes), the parameter stays.
    const shown = await status();
    await panel.scrollIntoViewIfNeeded();
    const box2 = (await panel.boundingBox())!;
    await page.mouse.move(box2.x + box2.width * 0.3, box2.y + box2.height * 0.7);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++)
      await page.mouse.move(box2.x + box2.width * 0.3 + 6 * i, box2.y + box2.height * 0.7);
    await page.mouse.up();
    await expect.poll(status).not.toEqual(shown);
    expect(await params()).toEqual([zb, zc]);

    // The arrow keys step zb (and zc), each one step.
    await panel.focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => (await params())[0]).toBeCloseTo(zb + 0.05, 5);

    // Two undos: the key step, then the click.
    await page.evaluate(() => window.__kleinflow!.store.undo());
    await page.evaluate(() => window.__kleinflow!.store.undo());
    await expect.poll(params).toEqual([-1.35, -0.3]);
  }, 180_000);
});
