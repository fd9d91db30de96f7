/**
 * Pictures in the WebGL2 runtime (src/viewport/picture-textures.ts), in real Chromium: the
 * built-in picture (uploaded at once) and a PNG data: URL (decoded with createImageBitmap, awaited
 * by renderToPixels) are sampled as the CPU reference samples them — picture colouring and
 * picture seeds.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Coloring, Scene } from '../../../nodes/core/scene.ts';
import { rasterize } from '../../../shader-gen/raster.ts';
import { scenePictures } from '../../../src/cli/scene-pictures.ts';
import { encodePng } from '../../../src/io/png.ts';
import { HAND_MADE_SCENES, makeScene, TRIANGLE_333 } from '../../shader-gen/support/scenes.ts';
import { compareImages } from './fixtures.ts';
import { decode, type HarnessPage, openHarness } from './page/open-page.ts';

let h: HarnessPage;
let page: Page;

beforeAll(async () => {
  h = await openHarness();
  page = h.page;
  await page.evaluate(() => window.kfViewport.create(160, 120, Number.POSITIVE_INFINITY));
});

afterAll(async () => {
  await h?.browser.close();
});

/** An 8×8 smooth gradient PNG (red across, green down) as a data: URL. */
function gradientPng(): string {
  const data = new Uint8ClampedArray(8 * 8 * 4);
  for (let y = 0; y < 8; y++)
    for (let x = 0; x < 8; x++) data.set([x * 32 + 16, y * 32 + 16, 96, 255], (y * 8 + x) * 4);
  return `data:image/png;base64,${Buffer.from(encodePng({ width: 8, height: 8, data })).toString('base64')}`;
}

async function gpuVsCpu(scene: Scene) {
  await page.evaluate((s: Scene) => window.kfViewport.setScene(s), scene);
  const opts = { width: 96, height: 72, samples: 2 };
  const { pixels } = await page.evaluate((o) => window.kfViewport.renderToPixels(o), opts);
  const cpu = rasterize(scene, { ...opts, pictures: scenePictures(scene) }).data;
  return compareImages(decode(pixels), new Uint8Array(cpu.buffer), 3);
}

describe('pictures on the GPU = on the CPU', () => {
  it('the built-in picture seen through the *333 kaleidoscope', async () => {
    const diff = await gpuVsCpu(HAND_MADE_SCENES['triangle-333-picture']);
    expect(diff.offShare).toBeLessThan(0.02);
  });

  it('picture and disk seeds with a tile fill', async () => {
    const diff = await gpuVsCpu(HAND_MADE_SCENES['schottky-seeds-fill-edges']);
    expect(diff.offShare).toBeLessThan(0.02);
  });

  it('a PNG picture from a data: URL (decoded asynchronously) draws as the CPU decodes it', async () => {
    const coloring: Coloring = {
      mode: 'image',
      image: { src: gradientPng(), width: 8, height: 8 },
      center: [0.5, 0.3],
      size: 0.8,
      rotation: 0.4,
    };
    const diff = await gpuVsCpu(makeScene(TRIANGLE_333, { coloring, scale: 3, center: [0.5, 0.3] }));
    expect(diff.offShare).toBeLessThan(0.02);
  });
});
