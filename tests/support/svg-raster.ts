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

/**
 * The drawn canvas as base64 text: raw RGBA or a PNG. Text, not an array of numbers: playwright
 * serialises a 320² picture's 409 600 numbers one by one (~8 s under load), a string in a blink.
 */
async function drawSvg(browser: Browser, svg: string, width: number, height: number, as: 'rgba' | 'png') {
  const page = await browser.newPage({ viewport: { width, height } });
  try {
    const base64 = await page.evaluate(
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
        if (as === 'png') return canvas.toDataURL('image/png').split(',')[1];
        const bytes = ctx.getImageData(0, 0, width, height).data;
        let binary = '';
        for (let i = 0; i < bytes.length; i += 0x8000)
          binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
        return btoa(binary);
      },
      { svg, width, height, as },
    );
    return new Uint8Array(Buffer.from(base64, 'base64'));
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
  const bytes = await drawSvg(browser, svg, width, height, 'rgba');
  return { width, height, data: new Uint8ClampedArray(bytes.buffer, bytes.byteOffset, bytes.byteLength) };
}

/** The SVG as PNG bytes. */
export async function svgToPng(
  browser: Browser,
  svg: string,
  width: number,
  height: number,
): Promise<Uint8Array> {
  return drawSvg(browser, svg, width, height, 'png');
}
