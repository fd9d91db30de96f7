/**
 * Mirrors that cannot silently break the picture, end to end in real Chromium: a teacher wires a
 * triangle's mirrors in the natural order AB, AC, BC — the AC mirror keeps the outside — sees the
 * warning naming it, clicks its fix and gets the tiling; a corner that is not π/n shows its angle as
 * π/x and one "Snap to (p, q, r)" makes the whole triangle exact.
 */

import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { repoRoot } from './app-server.ts';
import { appSessionForSuite } from './app-suite.ts';
import {
  diagnosticsList as listedList,
  listedDiagnostics as listedText,
  nodeEl,
  type PixelStats,
  renderPixels,
  setField,
  statusLine,
  thumbDiff,
  waitRendered,
} from './editor-page.ts';
import { buildTriangle } from './triangle-page.ts';

let page: Page;
const problems: string[] = [];
appSessionForSuite((s) => ({ page } = s), { problems });

const status = () => statusLine(page);
const diagnosticsList = () => listedList(page);
const listedDiagnostics = () => listedText(page);

async function zoomedOutPixels(): Promise<PixelStats> {
  await waitRendered(page);
  return renderPixels(page);
}

describe('mirrors', () => {
  // An equilateral triangle, anticlockwise: A, B along the bottom, C on top.
  const corners: (readonly [string, string])[] = [
    ['-1', '-0.5774'],
    ['1', '-0.5774'],
    ['0', '1.1547'],
  ];
  const points: string[] = [];
  const mirrors: string[] = [];

  it('AB, AC, BC: the AC mirror is named, its fix flips it, and the picture becomes the *333 tiling', async () => {
    // AB, AC, BC: the order a teacher writes them in.
    const built = await buildTriangle(page, corners);
    points.push(...built.points);
    mirrors.push(...built.mirrors);
    // The overlay hatches each mirror's back, so the kept side is visible in the picture.
    await expect.poll(() => page.locator(`[data-kept-side="${mirrors[1]}"]`).count()).toBeGreaterThan(0);

    // Never "No problems" for a wrong picture: a warning on the AC mirror names it.
    await expect.poll(() => status().textContent()).toMatch(/1 warning/);
    const text = await listedDiagnostics();
    expect(text).toContain('KF406');
    // Named by its title ("Line reflection 2": new nodes of a type get distinct ones), not its id.
    expect(text).toContain('“Line reflection 2” keeps the wrong side');
    expect(await nodeEl(page, mirrors[0]).getByRole('button', { name: /^Flip/ }).count()).toBe(0);
    const pane = (await page.getByTestId('render-pane').boundingBox())!;
    await page.mouse.move(pane.x + pane.width / 2, pane.y + pane.height / 2);
    for (let i = 0; i < 4; i++) await page.mouse.wheel(0, 300);
    const wrong = await zoomedOutPixels();
    mkdirSync(join(repoRoot, 'test-artifacts'), { recursive: true });
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'mirrors-wrong-side.png') });

    // One click on the node's fix: the flip toggle turns on, the warning goes, the tiling appears.
    await nodeEl(page, mirrors[1]).getByRole('button', { name: 'Flip “Line reflection 2”' }).click();
    await expect.poll(() => status().textContent()).toMatch(/No problems/);
    expect(await nodeEl(page, mirrors[1]).getByRole('checkbox', { name: 'flip' }).isChecked()).toBe(true);
    const tiling = await zoomedOutPixels();
    await page.screenshot({ path: join(repoRoot, 'test-artifacts', 'mirrors-flipped.png') });
    expect(tiling.sd).toBeGreaterThan(30);
    expect(tiling.colours).toBeGreaterThan(20);
    // Measured: wrong sd ≈ 32 with ≈ 80 colours, tiling sd ≈ 85 with ≈ 150, thumbnails ≈ 113 apart.
    expect(tiling.sd).toBeGreaterThan(wrong.sd + 20);
    expect(tiling.colours).toBeGreaterThan(wrong.colours);
    expect(thumbDiff(wrong, tiling)).toBeGreaterThan(20);

    // The fix is one undo step.
    await page.keyboard.press('Control+z');
    await expect.poll(() => status().textContent()).toMatch(/1 warning/);
    await page.keyboard.press('Control+y');
    await expect.poll(() => status().textContent()).toMatch(/No problems/);
    expect(problems).toEqual([]);
  }, 240_000);

  it('a corner that is not π/n shows π/x, and one "Snap to (p, q, r)" makes the triangle exact', async () => {
    // Lift C: the corners at A and B open beyond π/3 and C closes below it.
    await setField(page, points[2], 'y', '1.45');
    // Poll the list itself: the status line may count a warning a moment before the list shows it.
    await expect.poll(listedDiagnostics).toContain('KF407');
    const text = await listedDiagnostics();
    expect(text).toMatch(/at π\/\d\.\d+ \(\d+\.\d°\), not π\/n/);
    // The triangle snaps whole: the fix says the triple and which point moves where.
    const snap = diagnosticsList()
      .getByRole('button', { name: /^Snap to / })
      .first();
    const label = (await snap.textContent()) ?? '';
    expect(label).toMatch(/^Snap to \(3, 3, 3\): moves “Point \d” to \(-?[\d.]+, -?[\d.]+\)$/);
    const coords = () =>
      Promise.all(
        points.flatMap((p) =>
          ['x', 'y'].map((a) => nodeEl(page, p).locator(`input[aria-label="${a}"]`).inputValue()),
        ),
      );
    const before = await coords();
    // The status list re-renders while the picture refines, so under load the button is rarely
    // "stable" for Playwright's pointer click: send the click to the button itself.
    await snap.dispatchEvent('click');
    // One click leaves no warning at all, and the fix moved an upstream point node — the node that
    // owns the value, as a drag in the render does.
    await expect.poll(() => status().textContent()).toMatch(/No problems/);
    // (The graph's nodes redraw a frame after the status list: poll.)
    await expect.poll(coords).not.toEqual(before);
    expect(problems).toEqual([]);
  }, 120_000);
});
