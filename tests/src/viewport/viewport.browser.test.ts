/**
 * The Viewport in real Chromium (WebGL2 on SwiftShader): what a user sees on the canvas while
 * editing. The page is page/viewport-page.ts; images come back top row first.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { Scene, View } from '../../../nodes/core/scene.ts';
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { rasterize } from '../../../shader-gen/raster.ts';
import { FIG11 } from '../../shader-gen/space/scenes-3d.ts';
import { circlesScene, colourCount, compareImages, exampleScene } from './fixtures.ts';
import { decode, type HarnessPage, openHarness } from './page/open-page.ts';
import type { Quirks } from './page/viewport-page.ts';

let h: HarnessPage;
let page: Page;

beforeAll(async () => {
  h = await openHarness();
  page = h.page;
});

afterAll(async () => {
  await h?.browser.close();
});

const NO_BAKE = Number.POSITIVE_INFINITY;
const create = (
  w: number,
  ht: number,
  idleBakeMs = NO_BAKE,
  quirks: Partial<Quirks> = {},
  bandMs: number | undefined = undefined,
) =>
  page.evaluate(([w, ht, idle, q, b]) => window.kfViewport.create(w, ht, idle, q, b), [
    w,
    ht,
    idleBakeMs,
    quirks,
    bandMs,
  ] as const);
const setScene = (s: Scene | Scene3d) => page.evaluate((s) => window.kfViewport.setScene(s), s);
const setView = (v: View) => page.evaluate((v) => window.kfViewport.setView(v), v);
const stats = () => page.evaluate(() => window.kfViewport.stats());
const snapshot = async () => decode(await page.evaluate(() => window.kfViewport.snapshot()));
const diagnostics = () => page.evaluate(() => window.kfViewport.diagnostics);
/** Waits until `samples` samples are accumulated and the loop has gone quiet. */
const settle = async (samples: number) => {
  await page.evaluate((n) => window.kfViewport.waitSamples(n), samples);
  await page.evaluate(() => window.kfViewport.waitStill(250));
};

describe('Viewport', () => {
  it('draws the hyperbolic example as the CPU reference does', async () => {
    const scene = exampleScene('hyperbolic-237');
    await create(160, 120);
    await setScene(scene);
    await settle(scene.samples);
    const gpu = await snapshot();
    expect(colourCount(gpu)).toBeGreaterThan(8);
    const cpu = rasterize(scene, { width: 160, height: 120 }).data;
    // Sample-for-sample the same picture; pixels on a tile edge may round the other way in fp32.
    const diff = compareImages(gpu, new Uint8Array(cpu.buffer), 3);
    expect(diff.offShare).toBeLessThan(0.03);
    expect((await stats()).samples).toBe(scene.samples);
  });

  it('the canvas shows the resolved picture, encoded to sRGB by an sRGB drawing buffer', async () => {
    const scene = exampleScene('hyperbolic-237');
    await create(160, 120);
    await setScene(scene);
    await settle(scene.samples);
    // Chromium has drawingBufferStorage: the buffer encodes, the resolve shader does not.
    expect(await page.evaluate(() => window.kfViewport.canvasIsSrgb())).toBe(true);
    // A new frame (restarted by setView), captured as the page sees the canvas.
    const frame = page.evaluate(() => window.kfViewport.nextFrameShown());
    await setView(scene.view);
    const { shown, snapshot: resolved } = await frame;
    const diff = compareImages(decode(shown), decode(resolved), 1);
    expect(diff.offShare).toBe(0);
  });

  it('moving a circle changes the picture and compiles nothing', async () => {
    await create(128, 128);
    await setScene(circlesScene());
    await settle(8);
    const before = await snapshot();
    expect((await stats()).compiles).toBe(1);
    // A drag: one new scene per frame, same structure, new values.
    for (let i = 1; i <= 10; i++) {
      await setScene(circlesScene([-0.55 + 0.015 * i, -0.3]));
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(r)));
    }
    await settle(8);
    const after = await snapshot();
    expect(compareImages(before, after, 8).offShare).toBeGreaterThan(0.02);
    expect((await stats()).compiles).toBe(1);
    // A structural edit compiles once; going back to the old structure is a cache hit.
    await setScene(circlesScene([-0.4, -0.3], 8, true));
    await settle(8);
    expect((await stats()).compiles).toBe(2);
    await setScene(circlesScene([-0.4, -0.3]));
    await settle(8);
    expect((await stats()).compiles).toBe(2);
    expect(compareImages(await snapshot(), after, 0).offShare).toBe(0);
  });

  it('pan and zoom (setView) restart the accumulation without compiling', async () => {
    await create(128, 128);
    await setScene(circlesScene());
    await settle(8);
    const before = await snapshot();
    const framesBefore = (await stats()).frames;
    await setView({ center: [0.3, 0.2], scale: 1.5 });
    await settle(8);
    const s = await stats();
    expect(s.compiles).toBe(1);
    expect(s.frames - framesBefore).toBe(8);
    expect(compareImages(before, await snapshot(), 8).offShare).toBeGreaterThan(0.1);
  });

  it('accumulates to the target sample count, converging, then stops drawing', async () => {
    await create(128, 128);
    await page.evaluate(() => window.kfViewport.record(true));
    await setScene(circlesScene(undefined, 24));
    await settle(24);
    const frames = (await page.evaluate(() => window.kfViewport.record(false))).map(decode);
    expect(frames.length).toBe(24);
    // Successive frames differ less and less: the mean of 1/k of a new sample, about.
    const steps = frames.slice(1).map((f, i) => compareImages(frames[i], f).mean);
    const early = (steps[0] + steps[1] + steps[2]) / 3;
    const late = (steps.at(-1)! + steps.at(-2)! + steps.at(-3)!) / 3;
    expect(early).toBeGreaterThan(0);
    expect(late).toBeLessThan(early / 4);
    // Idle: no more frames while nothing changes, though the page keeps getting display frames.
    const s = await stats();
    await page.evaluate(async () => {
      for (let i = 0; i < 20; i++) await new Promise((r) => requestAnimationFrame(r));
    });
    expect(await stats()).toEqual(s);
    expect(s.samples).toBe(24);
  });

  it('bakes the values in when idle, draws the same picture, and leaves the bake on the next edit', async () => {
    await create(128, 128);
    await setScene(circlesScene());
    await settle(8);
    const uniform = await snapshot();
    await create(128, 128, 50);
    await setScene(circlesScene());
    await page.evaluate(() => window.kfViewport.waitBaked());
    await setView(circlesScene().view); // restart: every sample from the baked program
    await settle(8);
    const s = await stats();
    expect(s).toMatchObject({ compiles: 1, bakedCompiles: 1, baked: true });
    expect(compareImages(uniform, await snapshot(), 2).offShare).toBeLessThan(0.01);
    const framesBefore = s.frames;
    await setScene(circlesScene([-0.5, -0.3]));
    await settle(8);
    // The first frame after the edit already comes from the uniform program (no compile); the
    // baked one for the new values may take over later.
    const log = await page.evaluate(() => window.kfViewport.frameLog);
    expect(log[framesBefore]).toMatchObject({ samples: 1, baked: false });
    expect((await stats()).compiles).toBe(1);
  });

  it('survives a lost WebGL context: the same picture comes back by itself', async () => {
    await create(128, 128);
    await setScene(circlesScene());
    await settle(8);
    const before = await snapshot();
    const { frames } = await stats();
    await page.evaluate(() => window.kfViewport.loseAndRestoreContext());
    await page.evaluate((n) => window.kfViewport.waitFrames(n), frames + 8);
    await settle(8);
    expect(compareImages(before, await snapshot()).offShare).toBe(0);
    expect((await stats()).compiles).toBe(2);
  });

  it('a shader that fails keeps the last picture, names the node, and recovers', async () => {
    await create(128, 128);
    await setScene(circlesScene());
    await settle(8);
    const good = await snapshot();
    const shown = await page.locator('canvas').screenshot();
    await page.evaluate(() => window.kfViewport.injectError(4)); // inside the block of element 4 (c4)
    const broken = circlesScene(undefined, 8, true);
    await setScene(broken);
    await page.evaluate(() => window.kfViewport.waitStill(250));
    const reported = (await diagnostics()).at(-1)!;
    expect(reported.length).toBeGreaterThan(0);
    expect(reported[0]).toMatchObject({ code: 'KF403', severity: 'error', nodeId: 'c4' });
    expect(reported[0].message).toMatch(/kf_injected_error/);
    expect(compareImages(good, await snapshot()).offShare).toBe(0);
    expect((await page.locator('canvas').screenshot()).equals(shown)).toBe(true);
    // Pan while broken: still the last good picture, no crash.
    await setView({ center: [0.1, 0], scale: 3 });
    await page.evaluate(() => window.kfViewport.waitStill(250));
    expect((await page.locator('canvas').screenshot()).equals(shown)).toBe(true);
    // Fixed: the next scene compiles, the diagnostics clear.
    await page.evaluate(() => window.kfViewport.injectError(null));
    await setScene(broken);
    await settle(8);
    expect((await diagnostics()).at(-1)).toEqual([]);
    expect(compareImages(good, await snapshot(), 8).offShare).toBeGreaterThan(0.005);
    expect(h.errors).toEqual([]);
  });

  it('refuses to upload a NaN (dev builds throw) and draws again once the values are finite', async () => {
    await create(64, 64);
    await setScene(circlesScene());
    await settle(8);
    const good = await snapshot();
    const bad = circlesScene([Number.NaN, 0]);
    const errorsBefore = h.errors.length;
    await setScene(bad);
    await page.evaluate(() => window.kfViewport.waitStill(200));
    expect(h.errors.slice(errorsBefore).join('\n')).toMatch(/non-finite value/);
    expect(compareImages(good, await snapshot()).offShare).toBe(0);
    h.errors.length = errorsBefore;
    await setScene(circlesScene([-0.5, -0.3]));
    await settle(8);
    expect(compareImages(good, await snapshot(), 8).offShare).toBeGreaterThan(0.01);
    expect(h.errors).toEqual([]);
  });

  it('draws the same picture without EXT_float_blend (half-float running mean)', async () => {
    await create(96, 96);
    await setScene(circlesScene(undefined, 16));
    await settle(16);
    const sum = await snapshot();
    await create(96, 96, NO_BAKE, { noFloatBlend: true });
    await setScene(circlesScene(undefined, 16));
    await settle(16);
    expect(compareImages(sum, await snapshot(), 1).offShare).toBeLessThan(0.002);
  });

  it('with KHR_parallel_shader_compile, polls the bake over frames instead of waiting', async () => {
    await create(96, 96, 30, { parallelCompile: true });
    const queriesBefore = await page.evaluate(() => window.kfViewport.completionQueries());
    await setScene(circlesScene());
    await page.evaluate(() => window.kfViewport.waitBaked());
    // Two "still compiling" answers, then ready: at least three queries, one per frame.
    expect(
      (await page.evaluate(() => window.kfViewport.completionQueries())) - queriesBefore,
    ).toBeGreaterThanOrEqual(3);
    expect(await stats()).toMatchObject({ compiles: 1, bakedCompiles: 1, baked: true });
    expect(h.errors).toEqual([]);
  });
});

describe('Viewport: a slow full-size 3D sample is drawn in bands (frame-bands.ts)', () => {
  it('draws the same picture band by band as in one draw, and counts a sample once it is whole', async () => {
    const scene: Scene3d = { ...FIG11, samples: 4 };
    await create(64, 48, NO_BAKE, {}, Number.POSITIVE_INFINITY); // never in bands
    await setScene(scene);
    await settle(4);
    const whole = await snapshot();
    const wholeStats = await stats();
    expect(wholeStats.bands).toBe(1);
    // Any predicted time is "slow": once a frame is timed, every later sample is drawn in bands.
    await create(64, 48, NO_BAKE, {}, 1e-6);
    await setScene(scene);
    await settle(4);
    const s = await stats();
    expect(s.bands).toBeGreaterThan(1);
    // A frame per whole sample, not per band (and the first, reduced frame that timed the program).
    expect(s.frames).toBe(wholeStats.frames);
    expect(compareImages(await snapshot(), whole, 1).offShare).toBe(0);
    expect(h.errors).toEqual([]);
  });
});
