/**
 * Choosing a picture for the image node in the inspector: a small PNG is kept byte for byte with
 * its size, a picture longer than the side limit is shrunk to fit (not refused), a file that is not
 * a picture says so and changes nothing, the kaleidoscope shows the new picture, and Ctrl+Z brings
 * the old one back.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { LIMITS } from '../../nodes/core/limits.ts';
import { repoRoot } from './app-server.ts';
import { appSessionForSuite, inspectorOn } from './app-suite.ts';

const EXAMPLE = JSON.parse(
  readFileSync(join(repoRoot, 'examples/image-kaleidoscope-245.kleinflow.json'), 'utf8'),
);
const PIC = 'pic';

let page: Page;
appSessionForSuite((s) => ({ page } = s), { query: '?test', ready: inspectorOn(EXAMPLE, PIC) });

const inspector = () => page.getByRole('complementary', { name: 'Inspector' });
const params = () =>
  page.evaluate((id) => {
    const p = window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === id)!.params;
    return { src: String(p.src ?? ''), width: Number(p.width ?? 0), height: Number(p.height ?? 0) };
  }, PIC);
/** A PNG of w × h made in the page: left half red, right half blue (so the picture shows). */
const makePng = (w: number, h: number) =>
  page.evaluate(
    async ([w, h]) => {
      const c = new OffscreenCanvas(w, h);
      const g = c.getContext('2d')!;
      g.fillStyle = '#e02020';
      g.fillRect(0, 0, w / 2, h);
      g.fillStyle = '#2040e0';
      g.fillRect(w / 2, 0, w / 2, h);
      return Array.from(new Uint8Array(await (await c.convertToBlob({ type: 'image/png' })).arrayBuffer()));
    },
    [w, h] as const,
  );
const choose = async (name: string, mimeType: string, bytes: number[]) =>
  inspector()
    .getByLabel('Choose picture')
    .setInputFiles({ name, mimeType, buffer: Buffer.from(bytes) });
const exportPixels = () =>
  page.evaluate(async () =>
    Array.from((await window.__kleinflow!.viewport!.renderToPixels({ width: 32, height: 32, samples: 1 }))!),
  );

describe('Choose picture… on the image node', () => {
  it('keeps a small PNG as it is, with its size, and the kaleidoscope shows it', async () => {
    const before = await exportPixels();
    const png = await makePng(64, 32);
    await choose('halves.png', 'image/png', png);
    await expect.poll(async () => (await params()).width).toBe(64);
    const p = await params();
    expect(p.height).toBe(32);
    expect(Buffer.from(p.src.replace(/^data:image\/png;base64,/, ''), 'base64')).toEqual(Buffer.from(png));
    expect(await inspector().getByTestId('picture-status').textContent()).toContain('64 × 32');
    await expect
      .poll(async () => (await exportPixels()).join() !== before.join(), { timeout: 30_000 })
      .toBe(true);
  });

  it('shrinks a picture longer than the side limit instead of refusing it', async () => {
    const side = LIMITS.maxPictureSide;
    await choose('panorama.png', 'image/png', await makePng(side + 904, 200));
    await expect.poll(async () => (await params()).width, { timeout: 30_000 }).toBe(side);
    expect((await params()).height).toBe(Math.round((200 * side) / (side + 904)));
    expect(await page.locator('.react-flow__node[data-id="pic"] [title*="KF"]').count()).toBe(0);
  });

  it('says a text file is not a picture and keeps the picture; Ctrl+Z goes back one picture', async () => {
    const kept = await params();
    await choose('notes.txt', 'text/plain', Array.from(Buffer.from('not a picture')));
    await expect
      .poll(() => inspector().getByTestId('picture-status').textContent())
      .toContain('is not a picture');
    expect(await params()).toEqual(kept);
    await page.locator('.kf-graph').click({ position: { x: 20, y: 300 } });
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await params()).width).toBe(64);
  });
});
