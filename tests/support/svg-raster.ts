/**
 * Rasterises SVG text in headless Chromium (browser.ts): the SVG is drawn as an image onto a canvas
 * of its own size and read back as 8-bit RGBA, row 0 at the top (the CPU raster's layout), or as PNG.
 */
import type { Browser } from 'playwright-core';

export interface SvgPixels {
  readonly width: number;
  readonly height: number;
  readonly data: Uint8ClampedArray;
}

async function drawSvg(browser: Browser, svg: string, width: number, height: number, as: 'rgba' | 'png') {
  const page = await browser.newPage({ viewport: { width, height } });
  try {
    return await page.evaluate(
      async ({ svg, width, height, as }) => {
        const image = new Image();
        image.src = `data:image/svg+xml;base64,${btoa(unescape(encodeURIComponent(svg)))}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = width;
        canvas.height = height;
        const ctx = canvas.getContext('2d');
        if (!ctx) throw new Error('no 2D canvas');
        ctx.drawImage(image, 0, 0, width, height);
        if (as === 'png') return canvas.toDataURL('image/png');
        return Array.from(ctx.getImageData(0, 0, width, height).data);
      },
      { svg, width, height, as },
    );
  } finally {
    await page.close();
  }
}

export async function rasteriseSvg(
  browser: Browser,
  svg: string,
  width: number,
  height: number,
): Promise<SvgPixels> {
  const data = (await drawSvg(browser, svg, width, height, 'rgba')) as number[];
  return { width, height, data: Uint8ClampedArray.from(data) };
}

/** The SVG as PNG bytes. */
export async function svgToPng(
  browser: Browser,
  svg: string,
  width: number,
  height: number,
): Promise<Uint8Array> {
  const url = (await drawSvg(browser, svg, width, height, 'png')) as string;
  return Uint8Array.from(Buffer.from(url.slice(url.indexOf(',') + 1), 'base64'));
}
