/**
 * The live picture's schedule (src/viewport/frame-schedule.ts) with a fake GPU whose fences are
 * signalled when the test says: previews, full-size samples band by band over the preview, band
 * sizes paced to BAND_MS, and a change that drops the band at once.
 */
import { describe, expect, it } from 'vitest';
import { BAND_MS } from '../../../src/viewport/frame-bands.ts';
import { type FramePlan, FrameSchedule, type StepContext } from '../../../src/viewport/frame-schedule.ts';
import { DEFAULT_SCALE_POLICY } from '../../../src/viewport/render-scale.ts';

/** Just the fence calls of WebGL2 (gpu-fence.ts); `finish` signals every fence set so far. */
function fakeGpu() {
  const syncs = new Set<{ done: boolean }>();
  const gl = {
    SYNC_GPU_COMMANDS_COMPLETE: 1,
    SYNC_STATUS: 2,
    SIGNALED: 3,
    fenceSync: () => {
      const s = { done: false };
      syncs.add(s);
      return s;
    },
    getSyncParameter: (s: { done: boolean }) => (s.done ? 3 : 0),
    deleteSync: (s: { done: boolean }) => syncs.delete(s),
    flush: () => {},
  };
  return {
    gl: gl as unknown as WebGL2RenderingContext,
    finish: () => {
      for (const s of syncs) s.done = true;
    },
  };
}

const W = 320;
const H = 200;
const ctx = (is3d: boolean, target = 4): StepContext => ({
  is3d,
  target,
  width: W,
  height: H,
  drawable: true,
});
const SETTLED = DEFAULT_SCALE_POLICY.settleMs + 1;

/** A schedule with a fake clock (band times) and GPU; `send` plays the viewport's part for a plan. */
function setup() {
  let clock = 0;
  const gpu = fakeGpu();
  const s = new FrameSchedule(BAND_MS, () => clock);
  const send = (plan: FramePlan | null, is3d = true, startMs = clock) => {
    expect(plan).not.toBeNull();
    s.sent(gpu.gl, plan as FramePlan, startMs, is3d);
  };
  return { s, gpu, send, tick: (ms: number) => (clock += ms) };
}

/** A 3D schedule whose preview (1/8 scale) took 10 ms: a full-size sample is predicted at 640 ms. */
function previewed() {
  const t = setup();
  t.s.changed(0);
  t.s.newProgram();
  const preview = t.s.step(t.gpu.gl, 1, ctx(true)).plan;
  expect(preview).toMatchObject({ k: 0, scale: DEFAULT_SCALE_POLICY.minScale, rows: null });
  t.send(preview, true, -10); // sent 10 ms before the fake clock's 0, when it is polled
  t.gpu.finish();
  return t;
}

describe('FrameSchedule', () => {
  it('draws a 2D scene whole, one sample a frame up to the target, then nothing', () => {
    const { s, gpu, send } = setup();
    for (let k = 0; k < 4; k++) {
      const { plan, finished } = s.step(gpu.gl, k, ctx(false));
      expect(finished).toBeNull();
      expect(plan).toEqual({ k, scale: 1, size: { width: W, height: H }, rows: null });
      send(plan, false);
    }
    expect(s.step(gpu.gl, 5, ctx(false)).plan).toBeNull();
    expect(s.wantsFrames(4, true)).toBe(false);
    expect(s.fullSamples).toBe(4);
  });

  it('once still, draws a slow full-size sample in bands from the top, each shown over the preview', () => {
    const { s, gpu, send, tick } = previewed();
    const first = s.step(gpu.gl, SETTLED, ctx(true)).plan!;
    // 640 ms predicted over 200 rows: 15 rows take about 50 ms.
    expect(first).toEqual({ k: 0, scale: 1, size: { width: W, height: H }, rows: [H - 15, H] });
    send(first);
    // While the band is on the GPU nothing else is sent; the preview alone is shown.
    expect(s.step(gpu.gl, SETTLED + 16, ctx(true))).toEqual({ finished: null, plan: null });
    expect(s.shown()).toMatchObject({ base: 'preview', over: null });
    tick(BAND_MS);
    gpu.finish();
    // Finished: shown at once, and the next band sent in the same frame. It was seen 50 ms after it
    // was sent, up to one frame interval (17 ms) of which was waiting for the poll: 15 rows in 33 ms,
    // so the next band has 23 rows.
    const { finished, plan } = s.step(gpu.gl, SETTLED + 33, ctx(true));
    expect(finished).toEqual({ rows: 15, of: H, whole: false });
    expect(plan!.rows).toEqual([H - 38, H - 15]);
    expect(s.shown()).toEqual({
      base: 'preview',
      samples: 1,
      size: { width: W / 8, height: H / 8 },
      over: { rows: [H - 15, H], samples: 1 },
    });
    expect(s.progress).toEqual({ bands: 1, rows: 15, of: H });
    expect(s.fullSamples).toBe(0);
  });

  it('sizes each band from the time of the last, so each takes about BAND_MS', () => {
    const { s, gpu, send, tick } = previewed();
    let plan = s.step(gpu.gl, SETTLED, ctx(true)).plan;
    const sizes: number[] = [];
    for (const ms of [BAND_MS * 3, BAND_MS / 4, BAND_MS]) {
      send(plan);
      sizes.push(plan!.rows![1] - plan!.rows![0]);
      tick(ms);
      expect(s.step(gpu.gl, SETTLED, ctx(true)).plan).toBeNull(); // polled on the GPU: its time is its own
      gpu.finish();
      plan = s.step(gpu.gl, SETTLED, ctx(true)).plan;
    }
    // 15 rows took 3 × BAND_MS: 5; 5 took a quarter: at most twice as many, 10; 10 took BAND_MS: 10.
    expect(sizes).toEqual([15, 5, 10]);
    expect(plan!.rows![1] - plan!.rows![0]).toBe(10);
  });

  it('a band done within a frame grows; on slow frames it keeps its size; one that held the page shrinks', () => {
    const { s, gpu, send, tick } = previewed();
    let now = SETTLED;
    let plan = s.step(gpu.gl, now, ctx(true)).plan;
    const sizes: number[] = [];
    // Frames 16 ms apart, the band finished by the next: it took under a frame, so it doubles.
    for (let i = 0; i < 1; i++) {
      send(plan);
      sizes.push(plan!.rows![1] - plan!.rows![0]);
      tick(16);
      now += 16;
      gpu.finish();
      plan = s.step(gpu.gl, now, ctx(true)).plan;
    }
    // A loaded machine: frames 400 ms apart, the band seen at the next one: it keeps its size.
    for (let i = 0; i < 1; i++) {
      send(plan);
      sizes.push(plan!.rows![1] - plan!.rows![0]);
      tick(BAND_MS * 8);
      now += BAND_MS * 8;
      gpu.finish();
      plan = s.step(gpu.gl, now, ctx(true)).plan;
    }
    // The poll itself blocked until the band was done (SwiftShader): 600 ms past a 16 ms frame.
    send(plan);
    sizes.push(plan!.rows![1] - plan!.rows![0]);
    tick(616);
    now += 16;
    gpu.finish();
    plan = s.step(gpu.gl, now, ctx(true)).plan;
    sizes.push(plan!.rows![1] - plan!.rows![0]);
    // (The picture has 200 rows: 15 + 30 + 30 + 30 of them drawn.)
    expect(sizes).toEqual([15, 30, 30, 3]);
  });

  it('a whole banded sample counts once; the next sample starts from the learned band size', () => {
    const { s, gpu, send, tick } = previewed();
    let step = s.step(gpu.gl, SETTLED, ctx(true));
    let bands = 0;
    while (step.plan?.k === 0) {
      send(step.plan);
      bands++;
      tick(BAND_MS * 2); // every band twice as slow as aimed: the bands halve, down to one row
      s.step(gpu.gl, SETTLED, ctx(true)); // polled while on the GPU
      gpu.finish();
      step = s.step(gpu.gl, SETTLED, ctx(true));
    }
    expect(step.finished).toEqual({ rows: H, of: H, whole: true });
    expect(s.fullSamples).toBe(1);
    expect(s.bands).toBe(bands);
    expect(s.scale).toBe(1);
    expect(s.progress).toEqual({ bands: 0, rows: 0, of: H }); // the next sample began at once
    expect(step.plan).toEqual({ k: 1, scale: 1, size: { width: W, height: H }, rows: [H - 1, H] });
    send(step.plan);
    tick(BAND_MS);
    gpu.finish();
    s.step(gpu.gl, SETTLED, ctx(true));
    // Over a full-size picture, the accumulation target alone: its rows have 1 or 2 samples.
    expect(s.shown()).toMatchObject({ base: 'accumulation', samples: 1, over: null });
  });

  it('a change drops the band at once: the preview is sent without waiting for the GPU, and not timed', () => {
    const { s, gpu, send } = previewed();
    send(s.step(gpu.gl, SETTLED, ctx(true)).plan);
    s.step(gpu.gl, SETTLED + 16, ctx(true)); // takes the preview's timing; the band is still drawing
    s.changed(SETTLED + 20); // an orbit drag
    const { plan } = s.step(gpu.gl, SETTLED + 33, ctx(true));
    expect(plan).toMatchObject({ k: 0, rows: null });
    expect(plan!.scale).toBeLessThan(1);
    send(plan);
    expect(s.dynamic.measuring).toBe(false);
    expect(s.progress).toBeNull();
    expect(s.shown()).toMatchObject({ base: 'preview', over: null });
    // The abandoned band's fence is still polled until the GPU is done with it.
    expect(s.wantsFrames(4, true)).toBe(true);
    gpu.finish();
    s.step(gpu.gl, SETTLED + 50, ctx(true));
    expect(s.wantsFrames(4, true)).toBe(false);
  });

  it('draws nothing while no program can draw, and starts afresh after a lost context', () => {
    const { s, gpu } = previewed();
    expect(s.step(gpu.gl, SETTLED, { ...ctx(true), drawable: false }).plan).toBeNull();
    s.forget();
    expect(s.restarting).toBe(true);
    expect(s.step(gpu.gl, SETTLED, ctx(true)).plan).toMatchObject({ k: 0 });
  });
});
