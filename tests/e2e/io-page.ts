/** Helpers for the open/save/share/export suite: what a person does with files, links and the clipboard. */
import { readFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import type { Page } from 'playwright-core';
import { expect } from 'vitest';
import { decodePng } from '../../src/io/png.ts';
import { repoRoot } from './app-server.ts';

/** Clicks Save and returns the downloaded file's name and text. */
export async function saveViaButton(page: Page): Promise<{ name: string; text: string }> {
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.getByRole('button', { name: 'Save', exact: true }).click(),
  ]);
  return { name: download.suggestedFilename(), text: readFileSync((await download.path())!, 'utf8') };
}

/** The document as Save writes it now (parsed). */
export const currentDoc = async (page: Page): Promise<unknown> =>
  JSON.parse((await saveViaButton(page)).text);

/** Opens a file through the hidden file input (as the Open… button's picker would). */
export async function openViaPicker(page: Page, name: string, buffer: Buffer, mimeType = 'application/json') {
  await page.getByTestId('open-file').setInputFiles({ name, mimeType, buffer });
}

/**
 * Opens examples/`folder`/`id`.kleinflow.json through the picker and waits (up to `timeout` ms)
 * until the document Save writes has the example's title: the example is the open document.
 */
export async function openExampleFile(page: Page, id: string, folder = '', timeout = 30_000) {
  const path = join(repoRoot, 'examples', folder, `${id}.kleinflow.json`);
  const file = readFileSync(path);
  const title = JSON.parse(file.toString('utf8')).meta.title as string;
  await openViaPicker(page, basename(path), file);
  await expect
    .poll(async () => ((await currentDoc(page)) as { meta: { title: string } }).meta.title, { timeout })
    .toBe(title);
}

/** Drags a file over the window (the drop overlay must show) and drops it. */
export async function dropFile(page: Page, name: string, buffer: Buffer, mimeType: string): Promise<boolean> {
  const dt = await page.evaluateHandle(
    ({ name, b64, mimeType }) => {
      const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const t = new DataTransfer();
      t.items.add(new File([bytes], name, { type: mimeType }));
      return t;
    },
    { name, b64: buffer.toString('base64'), mimeType },
  );
  await page.dispatchEvent('body', 'dragenter', { dataTransfer: dt });
  await page.dispatchEvent('body', 'dragover', { dataTransfer: dt });
  // React renders the overlay on its next commit: wait for it (isVisible() alone does not wait).
  const overlay = await page
    .getByTestId('drop-overlay')
    .waitFor({ state: 'visible', timeout: 5_000 })
    .then(
      () => true,
      () => false,
    );
  await page.dispatchEvent('body', 'drop', { dataTransfer: dt });
  return overlay;
}

/** Pastes `text` as the browser's paste event would deliver it (focus on the page, not a field). */
export async function pasteText(page: Page, text: string) {
  await page.evaluate((t) => {
    const dt = new DataTransfer();
    dt.setData('text/plain', t);
    document.body.dispatchEvent(
      new ClipboardEvent('paste', { clipboardData: dt, bubbles: true, cancelable: true }),
    );
  }, text);
}

/** Chooses an item of a top-bar menu. */
export async function menu(page: Page, label: string, item: string) {
  await page.getByRole('button', { name: new RegExp(`^${label}`) }).click();
  await page.getByRole('menuitem', { name: new RegExp(item) }).click();
}

/**
 * Export → PNG image with `samples` per pixel (and the size, where given): the downloaded picture,
 * decoded. Waits up to two minutes for the download (SwiftShader renders it).
 */
export async function exportPng(
  page: Page,
  options: { readonly samples: number; readonly width?: number; readonly height?: number },
): Promise<ReturnType<typeof decodePng>> {
  await menu(page, 'Export', 'PNG image');
  const dialog = page.getByRole('dialog', { name: 'Export PNG' });
  if (options.width !== undefined) await dialog.getByLabel('Width in pixels').fill(String(options.width));
  if (options.height !== undefined) await dialog.getByLabel('Height in pixels').fill(String(options.height));
  await dialog.getByLabel('Samples').fill(String(options.samples));
  const [download] = await Promise.all([
    page.waitForEvent('download', { timeout: 120_000 }),
    dialog.getByRole('button', { name: /^Export \d+/ }).click(),
  ]);
  return decodePng(new Uint8Array(readFileSync((await download.path())!)));
}

/**
 * The render pane's pixels as shown (overlay hidden), RGBA, decoded by the browser from a
 * screenshot (the WebGL canvas does not keep its drawing buffer).
 */
export async function livePixels(page: Page): Promise<{ width: number; height: number; data: number[] }> {
  await page.addStyleTag({ content: '.kf-render-overlay{visibility:hidden}' });
  const png = await page.getByTestId('render-pane').screenshot();
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = Object.assign(document.createElement('canvas'), { width: img.width, height: img.height });
    const g = c.getContext('2d')!;
    g.drawImage(img, 0, 0);
    return {
      width: img.width,
      height: img.height,
      data: [...g.getImageData(0, 0, img.width, img.height).data],
    };
  }, png.toString('base64'));
}

const toLinear = (v: number) => {
  const c = v / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
};
const toSrgb = (l: number) => 255 * (l <= 0.0031308 ? l * 12.92 : 1.055 * l ** (1 / 2.4) - 0.055);

/**
 * Box-average downscale of 8-bit sRGB RGBA pixels by an integer factor, averaging in linear light
 * (as the renderer averages its samples), so an edge pixel comes out as the renderer would draw it.
 */
export function boxDownscale(src: { width: number; height: number; data: ArrayLike<number> }, k: number) {
  const width = Math.floor(src.width / k);
  const height = Math.floor(src.height / k);
  const out = new Float64Array(width * height * 4);
  const lut = Float64Array.from({ length: 256 }, (_, v) => toLinear(v));
  for (let y = 0; y < height * k; y++) {
    const row = Math.floor(y / k) * width;
    for (let x = 0; x < width * k; x++) {
      const o = (row + Math.floor(x / k)) * 4;
      const i = (y * src.width + x) * 4;
      for (let c = 0; c < 3; c++) out[o + c] += lut[Math.round(src.data[i + c])];
      out[o + 3] += src.data[i + 3];
    }
  }
  for (let i = 0; i < out.length; i++) out[i] = i % 4 === 3 ? out[i] / (k * k) : toSrgb(out[i] / (k * k));
  return { width, height, data: out };
}

/** Two RGBA pictures of one size next to each other (left | right), for looking at a comparison. */
export function sideBySide(a: { width: number; height: number; data: ArrayLike<number> }, b: typeof a) {
  const width = a.width * 2;
  const data = new Uint8ClampedArray(width * a.height * 4);
  for (let y = 0; y < a.height; y++) {
    for (let x = 0; x < a.width * 4; x++) {
      data[y * width * 4 + x] = a.data[y * a.width * 4 + x];
      data[y * width * 4 + a.width * 4 + x] = b.data[y * b.width * 4 + x];
    }
  }
  return { width, height: a.height, data };
}
