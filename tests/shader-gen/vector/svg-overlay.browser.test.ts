/**
 * The SVG's circles lie where the render draws its constant-width tile edges (the paper's Fig. 23
 * colouring): rasterised in Chromium, its stroke pixels and the CPU render's edge pixels overlay
 * within a pixel.
 */
import type { Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { rasterize } from '../../../shader-gen/raster.ts';
import { exportSvg } from '../../../shader-gen/vector/index.ts';
import { launchChromium } from '../../support/browser.ts';
import { loadExample } from '../../support/examples.ts';
import { rasteriseSvg } from '../../support/svg-raster.ts';

const W = 320;
const H = 320;

/** Pixels brighter than the dark tiles: the light edge (and limit) colour of Fig. 23. */
function brightMask(data: Uint8ClampedArray): Uint8Array {
  const mask = new Uint8Array(W * H);
  for (let i = 0; i < W * H; i++) {
    const o = i * 4;
    mask[i] = data[o] + data[o + 1] + data[o + 2] > 3 * 110 ? 1 : 0;
  }
  return mask;
}

/** Share of `a`'s set pixels with a set pixel of `b` within one pixel (3×3 neighbourhood). */
function coveredShare(a: Uint8Array, b: Uint8Array): number {
  let total = 0;
  let covered = 0;
  for (let y = 0; y < H; y++) {
    for (let x = 0; x < W; x++) {
      if (!a[y * W + x]) continue;
      total++;
      let hit = false;
      for (let dy = -1; dy <= 1 && !hit; dy++) {
        for (let dx = -1; dx <= 1 && !hit; dx++) {
          const xx = x + dx;
          const yy = y + dy;
          hit = xx >= 0 && yy >= 0 && xx < W && yy < H && b[yy * W + xx] === 1;
        }
      }
      if (hit) covered++;
    }
  }
  return covered / total;
}

describe('SVG export against the render (Fig. 23 constant-width edges)', () => {
  let browser: Browser;
  beforeAll(async () => {
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
  });

  it('draws its circles over the render’s edge pixels, within a pixel', async () => {
    const { scene } = loadExample('fig23-constant-width-circles');
    const svg = exportSvg(scene, { width: W, height: H, minRadius: 1 });
    if (!svg.ok) throw new Error(svg.message);
    const render = brightMask(rasterize(scene, { width: W, height: H, samples: 1 }).data);
    const vector = brightMask((await rasteriseSvg(browser, svg.svg, W, H)).data);
    const rendered = render.reduce((n, v) => n + v, 0);
    const drawn = vector.reduce((n, v) => n + v, 0);
    expect(drawn).toBeGreaterThan(W * 10);
    expect(rendered).toBeGreaterThan(W * 10);
    expect(coveredShare(vector, render)).toBeGreaterThan(0.97);
    expect(coveredShare(render, vector)).toBeGreaterThan(0.95);

    // The comparison sees a 3-pixel shift: the same SVG of a view moved right does not overlay.
    const px = scene.view.scale / H;
    const moved = {
      ...scene,
      view: { ...scene.view, center: [scene.view.center[0] + 3 * px, scene.view.center[1]] as const },
    };
    const shifted = exportSvg(moved, { width: W, height: H, minRadius: 1 });
    if (!shifted.ok) throw new Error(shifted.message);
    const off = brightMask((await rasteriseSvg(browser, shifted.svg, W, H)).data);
    expect(coveredShare(off, render)).toBeLessThan(0.9);
  });
});
