/**
 * Export rendering (Viewport.renderToPixels) in real Chromium: tiles stitch into exactly the
 * picture of one big tile, the picture is the CPU reference's, transparency, and cancelling.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Scene } from '../../../nodes/core/scene.ts';
import { rasterize } from '../../../shader-gen/raster.ts';
import { linearToSrgb } from '../../../shader-gen/srgb.ts';
import { colourCount, compareImages, exampleScene } from './fixtures.ts';
import { decode, type HarnessPage, openHarness } from './page/open-page.ts';

let h: HarnessPage;
let page: Page;
const scene = exampleScene('hyperbolic-237');

beforeAll(async () => {
  h = await openHarness();
  page = h.page;
  await page.evaluate(() => window.kfViewport.create(200, 150, Number.POSITIVE_INFINITY));
  await page.evaluate((s: Scene) => window.kfViewport.setScene(s), scene);
  await page.evaluate(() => window.kfViewport.waitSamples(1));
});

afterAll(async () => {
  await h?.browser.close();
});

type Opts = { width: number; height: number; samples: number; tile?: number; transparent?: boolean };
const render = (opts: Opts, cancelAt?: number) =>
  page.evaluate(([o, c]) => window.kfViewport.renderToPixels(o, c), [opts, cancelAt] as const);

describe('Viewport.renderToPixels', () => {
  it('stitches 256-pixel tiles into exactly the one-tile picture', async () => {
    const tiled = await render({ width: 600, height: 400, samples: 2, tile: 256 });
    const whole = await render({ width: 600, height: 400, samples: 2 });
    const a = decode(tiled.pixels);
    const b = decode(whole.pixels);
    expect(a.length).toBe(600 * 400 * 4);
    expect(colourCount(a)).toBeGreaterThan(3); // two tones, background, limit set and their mixes
    expect(compareImages(a, b).offShare).toBe(0);
    // 3 × 2 tiles × 2 samples = 12 steps of progress, ending at 1.
    expect(tiled.progress.length).toBe(12);
    expect(tiled.progress.at(-1)).toBe(1);
  });

  it('is the CPU reference picture, top row first', async () => {
    const { pixels } = await render({ width: 120, height: 90, samples: 3, tile: 64 });
    const cpu = rasterize(scene, { width: 120, height: 90, samples: 3 }).data;
    expect(compareImages(decode(pixels), new Uint8Array(cpu.buffer), 3).offShare).toBeLessThan(0.02);
  });

  it('encodes to sRGB as srgb.ts does, to the level (the SRGB8_ALPHA8 readback does it, not a shader)', async () => {
    // 256 linear values evenly spread in sRGB, the dark end (the linear segment) included.
    const linear = Array.from({ length: 256 }, (_, i) => (i / 255) ** 2.2);
    const got = await page.evaluate((l) => window.kfViewport.resolveLinear(l), linear);
    const want = linear.map((v) => Math.round(linearToSrgb(v) * 255));
    const off = got.map((g, i) => Math.abs(g - want[i]));
    expect(Math.max(...off)).toBeLessThanOrEqual(1);
    expect(off.filter((d) => d > 0).length).toBeLessThan(linear.length * 0.05);
  });

  it('makes the background outside the clip disk transparent on request', async () => {
    const px = decode((await render({ width: 80, height: 80, samples: 4, transparent: true })).pixels);
    const alpha = (x: number, y: number) => px[(y * 80 + x) * 4 + 3];
    expect(alpha(0, 0)).toBe(0); // a corner: outside the Poincaré disk
    expect(alpha(40, 40)).toBe(255); // the centre
    // The rim is antialiased: partly covered pixels are partly transparent.
    let partial = 0;
    for (let i = 3; i < px.length; i += 4) if (px[i] > 0 && px[i] < 255) partial++;
    expect(partial).toBeGreaterThan(20);
  });

  it('returns null when cancelled from onProgress', async () => {
    const r = await render({ width: 300, height: 200, samples: 8, tile: 128 }, 0.25);
    expect(r.pixels).toBeNull();
    expect(r.progress.at(-1)).toBeGreaterThanOrEqual(0.25);
    expect(r.progress.at(-1)).toBeLessThan(0.3);
    expect(h.errors).toEqual([]);
  });
});
