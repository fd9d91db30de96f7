/**
 * Helpers that drive the editor like a person does (mouse, keyboard), for the e2e suites:
 * palette, wiring by dragging between handles, reading the render's pixels.
 */
import type { Page } from 'playwright-core';

/** The node under test's React Flow element. */
export const nodeEl = (page: Page, id: string) => page.locator(`.react-flow__node[data-id="${id}"]`);

export const handle = (page: Page, nodeId: string, side: 'in' | 'out', port: string) =>
  page.locator(`.react-flow__handle[data-nodeid="${nodeId}"][data-handleid="${side}:${port}"]`);

export async function graphBox(page: Page) {
  const box = await page.locator('.kf-graph').boundingBox();
  if (!box) throw new Error('graph pane not visible');
  return box;
}

/** Opens the palette with Space at (x, y) in the graph pane, searches, picks the first match; returns the new node's id. */
export async function addNode(page: Page, query: string, x: number, y: number): Promise<string> {
  const g = await graphBox(page);
  await page.mouse.move(g.x + x, g.y + y);
  await page.keyboard.press('Space');
  const input = page.getByRole('combobox', { name: 'Search node types' });
  await input.waitFor();
  await input.fill(query);
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
  const selected = page.locator('.react-flow__node.selected');
  await selected.first().waitFor();
  return (await selected.first().getAttribute('data-id'))!;
}

async function centre(locator: ReturnType<Page['locator']>) {
  const b = await locator.boundingBox();
  if (!b) throw new Error('handle not visible');
  return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
}

/**
 * The centre of `locator` once it stays put across two animation frames: a node just added may
 * still be moving (the canvas pans to keep it in view), and a drop aimed at where a handle was
 * lands beside it.
 */
async function restingCentre(page: Page, locator: ReturnType<Page['locator']>) {
  const frames = () =>
    page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  let last = await centre(locator);
  for (let i = 0; i < 100; i++) {
    await frames();
    const now = await centre(locator);
    if (now.x === last.x && now.y === last.y) return now;
    last = now;
  }
  return last;
}

/** Drags a wire from an output handle to an input handle with real pointer moves. */
export async function drag(page: Page, from: ReturnType<Page['locator']>, to: ReturnType<Page['locator']>) {
  const a = await restingCentre(page, from);
  const b = await restingCentre(page, to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move((a.x + b.x) / 2, (a.y + b.y) / 2, { steps: 4 });
  await page.mouse.move(b.x, b.y, { steps: 4 });
  await page.mouse.up();
}

export async function connect(page: Page, from: string, outPort: string, to: string, inPort: string) {
  await drag(page, handle(page, from, 'out', outPort), handle(page, to, 'in', inPort));
}

/** Types a value into a node's number field (by its aria-label) and commits it with Enter. */
export async function setField(page: Page, nodeId: string, label: string, value: string) {
  const input = nodeEl(page, nodeId).locator(`input[aria-label="${label}"]`);
  await input.click();
  await input.fill(value);
  await input.press('Enter');
}

export const edgeCount = (page: Page) => page.locator('.react-flow__edge').count();
export const nodeCount = (page: Page) => page.locator('.react-flow__node').count();

/**
 * Waits until the status line says the picture has all its samples. When it never does, the error
 * says what the status line and the viewport's counters showed (a stalled render is then told
 * apart from a slow one).
 */
export async function waitRendered(page: Page, timeout = 60_000) {
  try {
    await page
      .getByTestId('render-progress')
      .filter({ hasText: /^Rendered/ })
      .waitFor({ timeout });
  } catch (e) {
    const seen = await page
      .evaluate(() => ({
        status: document.querySelector('[data-testid="render-progress"]')?.textContent ?? null,
        stats: window.__kleinflow?.viewport ? JSON.stringify(window.__kleinflow.viewport.stats) : null,
      }))
      .catch(() => null);
    throw new Error(`not rendered within ${timeout} ms; status ${JSON.stringify(seen)}`, { cause: e });
  }
}

export interface PixelStats {
  readonly mean: number;
  /** Standard deviation of each colour channel over the picture, averaged over R, G, B. */
  readonly sd: number;
  /** Distinct colours after quantising each channel to 4 bits. */
  readonly colours: number;
  /** 32×32 RGB thumbnail, for comparing two renders. */
  readonly thumb: number[];
}

/**
 * Pixel statistics of the render pane as shown on screen: a screenshot decoded by the browser
 * itself (the WebGL canvas does not keep its drawing buffer, so it cannot be read back directly).
 */
export async function renderPixels(page: Page): Promise<PixelStats> {
  const png = await page.getByTestId('render-pane').screenshot();
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = 32;
    c.height = 32;
    const g = c.getContext('2d')!;
    g.drawImage(img, 0, 0, 32, 32);
    const d = g.getImageData(0, 0, 32, 32).data;
    const s = [0, 0, 0];
    const s2 = [0, 0, 0];
    const set = new Set<number>();
    const thumb: number[] = [];
    for (let i = 0; i < d.length; i += 4) {
      for (let k = 0; k < 3; k++) {
        thumb.push(d[i + k]);
        s[k] += d[i + k];
        s2[k] += d[i + k] ** 2;
      }
      set.add(((d[i] >> 4) << 8) | ((d[i + 1] >> 4) << 4) | (d[i + 2] >> 4));
    }
    const n = d.length / 4;
    const sd = [0, 1, 2].map((k) => Math.sqrt(Math.max(0, s2[k] / n - (s[k] / n) ** 2)));
    return {
      mean: (s[0] + s[1] + s[2]) / (3 * n),
      sd: (sd[0] + sd[1] + sd[2]) / 3,
      colours: set.size,
      thumb,
    };
  }, png.toString('base64'));
}

/** Mean absolute difference of two thumbnails (0 = identical). */
export const thumbDiff = (a: PixelStats, b: PixelStats) =>
  a.thumb.reduce((sum, v, i) => sum + Math.abs(v - b.thumb[i]), 0) / a.thumb.length;

/** A point of the graph pane with empty canvas around it (60 px each way), scanning from the top-left. */
export async function emptyCanvasPoint(page: Page): Promise<{ x: number; y: number }> {
  const found = await page.evaluate(() => {
    const pane = document.querySelector('.kf-graph')!.getBoundingClientRect();
    const free = (x: number, y: number) =>
      document.elementFromPoint(x, y)?.classList.contains('react-flow__pane') ?? false;
    for (let y = pane.top + 120; y < pane.bottom - 160; y += 40) {
      for (let x = pane.left + 80; x < pane.right - 220; x += 40) {
        if ([-60, 0, 60].every((dx) => [-60, 0, 60].every((dy) => free(x + dx, y + dy)))) return { x, y };
      }
    }
    return null;
  });
  if (!found) throw new Error('no empty canvas left in the graph pane');
  return found;
}

/** The status line's diagnostics count (a button that opens the list). */
export const statusLine = (page: Page) => page.getByTestId('diagnostics-count');
export const diagnosticsList = (page: Page) => page.getByRole('list', { name: 'Diagnostics' });

/** Opens the status line's list of diagnostics (if closed) and returns its text. */
export async function listedDiagnostics(page: Page): Promise<string> {
  if ((await statusLine(page).getAttribute('aria-expanded')) !== 'true') await statusLine(page).click();
  return (await diagnosticsList(page).textContent()) ?? '';
}
