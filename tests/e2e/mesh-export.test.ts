/**
 * Export → Mesh in real Chromium: the Fig. 26 quasi-sphere downloads as a binary STL whose
 * mesh is closed and consistently oriented, with the triangle count in the toast, and as a 3MF
 * with its colour group when that format is chosen, scaled to the Print size typed after the Box
 * (reached with Tab; a bad size is refused in the dialog) with its size in mm in the toast; the infinite sphairahedron without a box says
 * that one is needed, in the dialog, and downloads nothing.
 */
import { readFileSync } from 'node:fs';
import { unzipSync } from 'fflate';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { readStl } from '../../src/io/stl.ts';
import { appSessionForSuite } from './app-suite.ts';
import { menu, openExampleFile } from './io-page.ts';
import { openSmall3dPane } from './view-3d-page.ts';

/** The Export menu's item (a regular expression: the parenthesis is escaped). */
const MESH_ITEM = 'Mesh \\(3D print';

let page: Page;
// A small render pane (view-3d-page.ts); the export does not depend on it.
appSessionForSuite((s) => ({ page } = s), { open: openSmall3dPane });

async function openExample(id: string) {
  await openExampleFile(page, id, '3d', 90_000);
  // The picture is not what is tested: make the sphere tracer cheap (march steps and shading are
  // values only — the mesh depends on the geometry and max iterations, which stay as they are),
  // so the page is not frozen by SwiftShader while the test clicks the menus.
  await page.evaluate(() =>
    window.__kleinflow!.store.dispatchSilently({
      type: 'set-params',
      patches: [{ nodeId: 'render', params: { samples: 1, marchSteps: 16, occlusion: 0, shadow: 0 } }],
    }),
  );
}

describe('Export → Mesh', () => {
  it('downloads the quasi-sphere as a closed, oriented STL and says how many triangles', async () => {
    await openExample('fig26-quasi-sphere');
    await menu(page, 'Export', MESH_ITEM);
    const dialog = page.getByRole('dialog', { name: 'Export mesh' });
    await dialog.getByLabel('Resolution').fill('16');
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 90_000 }),
      dialog.getByRole('button', { name: /^Export STL 16/ }).click(),
    ]);
    expect(download.suggestedFilename()).toMatch(/\.stl$/);
    const { triangles } = readStl(new Uint8Array(readFileSync((await download.path())!)));
    expect(triangles.length).toBeGreaterThan(100);
    const directed = new Map<string, number>();
    for (const t of triangles)
      for (let e = 0; e < 3; e++) {
        const k = `${t.vertices[e].join(',')}>${t.vertices[(e + 1) % 3].join(',')}`;
        directed.set(k, (directed.get(k) ?? 0) + 1);
      }
    for (const [k, n] of directed) {
      const [a, b] = k.split('>');
      expect(n === 1 && directed.get(`${b}>${a}`) === 1).toBe(true);
    }
    const toast = await page.getByTestId('toast').textContent();
    expect(Number(/(\d+) triangles/.exec(toast ?? '')?.[1])).toBe(triangles.length);
    // No print size: one unit is 1 mm, and the toast says how large that is.
    expect(toast).toMatch(/triangles, [\d.]+ × [\d.]+ × [\d.]+ mm \(one unit = 1 mm: set Print size/);
  }, 240_000);

  it('downloads a 3MF with the render’s colours at the Print size when that format is chosen', async () => {
    await openExample('fig26-quasi-sphere');
    await menu(page, 'Export', MESH_ITEM);
    const dialog = page.getByRole('dialog', { name: 'Export mesh' });
    await dialog.getByLabel('Format').selectOption('3mf');
    await dialog.getByLabel('Resolution').fill('12');
    // The print size is the field after the Box, typed from the keyboard.
    await dialog.getByLabel('Box').focus();
    await page.keyboard.press('Tab');
    await expect.poll(() => page.evaluate(() => document.activeElement?.id)).toBe('kf-mesh-print-size');
    await page.keyboard.type('0');
    await expect
      .poll(() => dialog.getByRole('alert').textContent())
      .toMatch(/Print size: must be between 1 and 10000 mm/);
    expect(await dialog.getByRole('button', { name: /^Export 3MF/ }).isDisabled()).toBe(true);
    await page.keyboard.press('Backspace');
    await page.keyboard.type('60');
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 90_000 }),
      dialog.getByRole('button', { name: /^Export 3MF 12³, 60 mm/ }).click(),
    ]);
    expect(download.suggestedFilename()).toMatch(/\.3mf$/);
    const files = unzipSync(new Uint8Array(readFileSync((await download.path())!)));
    const model = new TextDecoder().decode(files['3D/3dmodel.model']);
    expect((model.match(/<m:color color="#[0-9A-F]{6}"\/>/g) ?? []).length).toBeGreaterThan(3);
    const triangles = model.match(/<triangle [^>]*p1="\d+" p2="\d+" p3="\d+"\/>/g) ?? [];
    const toast = await page.getByTestId('toast').textContent();
    expect(toast).toMatch(/3MF mesh/);
    expect(Number(/(\d+) triangles/.exec(toast ?? '')?.[1])).toBe(triangles.length);
    // Scaled so that the longest side is 60 mm, as the toast says.
    const vertices = [...model.matchAll(/<vertex x="([^"]+)" y="([^"]+)" z="([^"]+)"\/>/g)];
    const side = (a: number) => {
      const v = vertices.map((m) => Number(m[a + 1]));
      return Math.max(...v) - Math.min(...v);
    };
    expect(Math.max(side(0), side(1), side(2))).toBeCloseTo(60, 4);
    expect(toast).toMatch(/triangles, [\d.]+ × 60\.0 × [\d.]+ mm\./);
  }, 240_000);

  it('asks for a box when plane mirrors repeat the solid without end, and downloads nothing', async () => {
    await openExample('fig28-fractal-terrain');
    let downloaded = false;
    page.on('download', () => {
      downloaded = true;
    });
    await menu(page, 'Export', MESH_ITEM);
    const dialog = page.getByRole('dialog', { name: 'Export mesh' });
    await dialog.getByLabel('Resolution').fill('8');
    await dialog.getByRole('button', { name: /^Export STL 8/ }).click();
    await expect
      .poll(() => dialog.getByRole('alert').textContent(), { timeout: 90_000 })
      .toMatch(/unbounded.*give bounds/);
    expect(downloaded).toBe(false);
  }, 240_000);
});
