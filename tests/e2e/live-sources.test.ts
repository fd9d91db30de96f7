/**
 * Live sources end to end in Chromium with its fake camera (`--use-fake-device-for-media-stream`:
 * a moving test pattern; `--use-fake-ui-for-media-stream`: the permission prompt says yes). A
 * webcam document asks for nothing on load; "Start camera" makes the kaleidoscope follow the
 * camera frame by frame with no recompile; a denied camera leaves a node message and the fallback
 * picture; a video recorded in the page from the fake camera plays from the inspector's file input
 * and follows the animation time, and Export animation draws it frame by frame.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { BrowserContext, Page } from 'playwright-core';
import { beforeAll, describe, expect, it } from 'vitest';
import { countGifFrames, gifFrameBlocks } from '../../src/io/gif.ts';
import { repoRoot, type ServedApp } from './app-server.ts';
import { servedAppForSuite } from './app-suite.ts';
import { nodeEl, renderPixels } from './editor-page.ts';
import { menu } from './io-page.ts';

let app: ServedApp;
const EXAMPLE = JSON.parse(
  readFileSync(join(repoRoot, 'examples', 'webcam-kaleidoscope.kleinflow.json'), 'utf8'),
);
const CAMERA_ID = 'cam';

servedAppForSuite(
  (served) => {
    app = served;
  },
  { launchArgs: ['--use-fake-device-for-media-stream', '--use-fake-ui-for-media-stream'] },
);

const stats = (page: Page) => page.evaluate(() => window.__kleinflow!.viewport!.stats);

/** A page with the webcam example loaded, counting getUserMedia calls in `window.__cameraAsks`. */
async function openExample(context: BrowserContext): Promise<Page> {
  await context.addInitScript(() => {
    const w = window as unknown as { __cameraAsks: number };
    w.__cameraAsks = 0;
    const media = navigator.mediaDevices;
    const ask = media.getUserMedia.bind(media);
    media.getUserMedia = (c) => {
      w.__cameraAsks++;
      return ask(c);
    };
  });
  const page = await context.newPage();
  page.setDefaultTimeout(60_000);
  await page.goto(`${app.url}?test`);
  await page.waitForFunction(() => window.__kleinflow?.viewport);
  await page.evaluate((d) => window.__kleinflow!.store.dispatch({ type: 'load-document', doc: d }), EXAMPLE);
  await page.waitForFunction(() => window.__kleinflow!.viewport!.stats.samples >= 1);
  return page;
}

/** The messages on a node's badge (code and text). */
const nodeMessages = (page: Page, id: string) =>
  nodeEl(page, id).locator('[title*="KF"]').first().getAttribute('title');

/** A small export of the picture as it is now: one sample, so the same frame gives the same pixels. */
const exportPixels = (page: Page) =>
  page.evaluate(async () =>
    Array.from((await window.__kleinflow!.viewport!.renderToPixels({ width: 32, height: 32, samples: 1 }))!),
  );
const differing = (a: number[], b: number[]) => a.filter((v, i) => v !== b[i]).length;

describe('webcam', () => {
  let page: Page;
  beforeAll(async () => {
    page = await openExample(await app.newContext());
  }, 120_000);

  it('asks for nothing on load: the node says the camera is off, Start camera shows, the fallback is drawn', async () => {
    await page.getByRole('button', { name: 'Start camera' }).waitFor();
    expect(await page.evaluate(() => (window as unknown as { __cameraAsks: number }).__cameraAsks)).toBe(0);
    expect(await nodeMessages(page, CAMERA_ID)).toContain('KF321');
    expect((await renderPixels(page)).sd).toBeGreaterThan(20); // the checker, not a blank pane
  });

  it('Start camera: the picture follows the fake camera frame by frame, with no recompile', async () => {
    const fallback = await exportPixels(page);
    const before = await stats(page);
    await page.getByRole('button', { name: 'Start camera' }).click();
    await page.getByRole('button', { name: 'Start camera' }).waitFor({ state: 'detached' });
    await page.waitForFunction(
      (n) => window.__kleinflow!.viewport!.stats.liveUploads > n + 3,
      before.liveUploads,
    );
    // The fake camera's pattern moves: a later export differs from this one (one frame gives equal
    // ones). Under load the fake camera's frames come slower, so look again until it has moved.
    const a = await exportPixels(page);
    let b = a;
    await expect
      .poll(
        async () => {
          b = await exportPixels(page);
          return differing(a, b);
        },
        { timeout: 20_000, interval: 700 },
      )
      .toBeGreaterThan(20);
    const after = await stats(page);
    expect(after.compiles).toBe(before.compiles);
    expect(after.frames).toBeGreaterThan(before.frames + 3);
    await expect.poll(() => nodeEl(page, CAMERA_ID).locator('[title*="KF32"]').count()).toBe(0);
    // The PNG export draws the camera's frame, not the fallback.
    expect(differing(b, fallback)).toBeGreaterThan(1000);
  }, 120_000);

  it('back to the picture: the camera stops and so do the frames', async () => {
    const compiles = (await stats(page)).compiles;
    await page.evaluate((id) => {
      window.__kleinflow!.store.dispatch({
        type: 'set-params',
        patches: [{ nodeId: id, params: { source: 'picture' } }],
      });
    }, CAMERA_ID);
    await page
      .getByTestId('render-progress')
      .filter({ hasText: /^Rendered/ })
      .waitFor();
    const frames = (await stats(page)).frames;
    await page.waitForTimeout(600);
    const now = await stats(page);
    expect(now.frames).toBe(frames); // no live source: no frames requested
    expect(now.compiles).toBe(compiles);
  }, 60_000);
});

describe('denied camera', () => {
  it('says why on the node and draws the fallback picture', async () => {
    const context = await app.newContext();
    // The browser's answer when the user (or a policy) says no. The fake-UI flag grants every
    // request, and a CDP "denied" permission does not hold against it, so the answer is given here.
    await context.addInitScript(() => {
      navigator.mediaDevices.getUserMedia = () =>
        Promise.reject(new DOMException('Permission denied', 'NotAllowedError'));
    });
    const page = await openExample(context);
    await page.getByRole('button', { name: 'Start camera' }).click();
    await expect.poll(() => nodeMessages(page, CAMERA_ID), { timeout: 20_000 }).toContain('KF320');
    expect(await nodeMessages(page, CAMERA_ID)).toContain('permission was denied');
    await page
      .getByTestId('render-progress')
      .filter({ hasText: /^Rendered/ })
      .waitFor();
    expect((await renderPixels(page)).sd).toBeGreaterThan(20);
    await context.close();
  }, 120_000);
});

describe('video file', () => {
  it('a video chosen in the inspector plays in the kaleidoscope; a small one is kept in the document', async () => {
    const context = await app.newContext();
    const page = await openExample(context);
    await page.evaluate((id) => {
      const { store } = window.__kleinflow!;
      store.dispatch({ type: 'set-params', patches: [{ nodeId: id, params: { source: 'video' } }] });
      store.setSelection([id]);
    }, CAMERA_ID);
    await expect.poll(() => nodeMessages(page, CAMERA_ID)).toContain('KF322');
    // A 1.2 s WebM of the fake camera's moving pattern, recorded in the page (a recorded canvas
    // gives no frames in headless Chromium).
    const webm = await page.evaluate(async () => {
      const stream = await navigator.mediaDevices.getUserMedia({ video: { width: 64, height: 48 } });
      const rec = new MediaRecorder(stream, { mimeType: 'video/webm' });
      const chunks: Blob[] = [];
      rec.ondataavailable = (e) => chunks.push(e.data);
      const stopped = new Promise((r) => {
        rec.onstop = r;
      });
      rec.start(100);
      await new Promise((r) => setTimeout(r, 1200));
      rec.stop();
      await stopped;
      for (const t of stream.getTracks()) t.stop();
      return Array.from(new Uint8Array(await new Blob(chunks).arrayBuffer()));
    });
    expect(webm.length).toBeGreaterThan(1000);
    const before = await stats(page);
    await page.getByRole('button', { name: 'Inspector' }).click();
    const inspector = page.getByRole('complementary', { name: 'Inspector' });
    await inspector
      .getByLabel('Choose video')
      .setInputFiles({ name: 'loop.webm', mimeType: 'video/webm', buffer: Buffer.from(webm) });
    await page.waitForFunction(
      (n) => window.__kleinflow!.viewport!.stats.liveUploads > n + 3,
      before.liveUploads,
    );
    await expect.poll(() => inspector.getByTestId('live-status').textContent()).toContain('live');
    const params = await page.evaluate(
      (id) => window.__kleinflow!.store.getState().doc.nodes.find((n) => n.id === id)!.params,
      CAMERA_ID,
    );
    expect(params.video).toBe('loop.webm');
    expect(String(params.videoSrc)).toMatch(/^data:video\/webm/);
    expect((await stats(page)).compiles).toBe(before.compiles);
    await expect.poll(() => nodeEl(page, CAMERA_ID).locator('[title*="KF32"]').count()).toBe(0);

    // With a Time node the video follows the animation time, modulo its length, and holds still.
    const videoAt = () =>
      page.evaluate(() => {
        const v = window.__kleinflow!.live.frameOf('video:cam')?.video;
        return v ? { time: v.currentTime, duration: v.duration, paused: v.paused } : null;
      });
    // The source reports no frame while the video seeks, loads its metadata or wraps round its loop
    // (frameOf is null then), so each read waits for a moment it has one.
    type VideoNow = NonNullable<Awaited<ReturnType<typeof videoAt>>>;
    const videoWhen = async (ok: (v: VideoNow) => boolean): Promise<VideoNow> => {
      const seen: { last: VideoNow | null } = { last: null };
      await expect
        .poll(
          async () => {
            seen.last = await videoAt();
            return seen.last !== null && ok(seen.last);
          },
          { timeout: 20_000 },
        )
        .toBe(true);
      return seen.last!;
    };
    const { duration } = await videoWhen((v) => v.duration > 0.5);
    expect(Number.isFinite(duration)).toBe(true);
    await page.evaluate(() => {
      const { store } = window.__kleinflow!;
      store.dispatch({ type: 'add-node', node: { id: 'T', type: 'time', position: [0, 500], params: {} } });
      store.setTime(0.4);
    });
    await expect.poll(async () => (await videoAt())?.time ?? -1, { timeout: 20_000 }).toBeCloseTo(0.4, 1);
    expect((await videoWhen(() => true)).paused).toBe(true);
    await page.evaluate((t) => window.__kleinflow!.store.setTime(t), 0.3 + 2 * duration);
    await expect.poll(async () => (await videoAt())?.time ?? -1, { timeout: 20_000 }).toBeCloseTo(0.3, 1);
    expect((await stats(page)).compiles).toBe(before.compiles);

    // Export animation plays the video in the file: frame i shows it at t = i / fps (the graph
    // itself does not move: only the video makes the frames differ). Afterwards it follows the
    // timeline again.
    await menu(page, 'Export', 'Animation');
    const dialog = page.getByRole('dialog', { name: 'Export animation' });
    await dialog.locator('#kf-anim-format[data-checked="true"]').waitFor();
    await dialog.getByLabel('Format').selectOption('gif');
    await dialog.getByLabel('Width in pixels').fill('48');
    await dialog.getByLabel('Height in pixels').fill('48');
    await dialog.getByLabel('Frames/s').fill('4');
    await dialog.getByLabel('Samples').fill('1');
    await dialog.getByLabel('Duration in seconds').fill('1');
    const [download] = await Promise.all([
      page.waitForEvent('download', { timeout: 90_000 }),
      dialog.getByRole('button', { name: 'Export 4 frames' }).click(),
    ]);
    const gif = new Uint8Array(readFileSync((await download.path())!));
    expect(countGifFrames(gif)).toBe(4);
    const distinct = new Set(gifFrameBlocks(gif).map((b) => Buffer.from(b).toString('base64')));
    expect(distinct.size).toBe(4);
    await expect.poll(async () => (await videoAt())?.time ?? -1, { timeout: 20_000 }).toBeCloseTo(0.3, 1);
    await context.close();
  }, 180_000);
});
