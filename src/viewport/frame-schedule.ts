/**
 * What the live picture draws next and what the canvas shows meanwhile; the viewport does the GL
 * draws. Each animation frame asks `step` for a plan: a whole frame (a 2D sample, a 3D preview at
 * the dynamic scale of dynamic-resolution.ts, a fast full-size 3D sample) or the next band of a
 * slow full-size 3D sample (frame-bands.ts).
 *
 * A preview is drawn into a target of its own, so the first full-size sample can be drawn band by
 * band into the accumulation target while the canvas shows the preview with the finished rows over
 * it (`shown`). One band is on the GPU at a time: the loop does not wait for the GPU, so without a
 * fence every band would be queued at once and the GPU (and the compositor behind it) be as busy as
 * with one big draw. A finished band is shown, timed (sizing the next) and followed by the next in
 * the same animation frame. A change (drag, edit) drops the band at once: the preview it asks for
 * is sent without waiting for the abandoned band, which the GPU finishes first (GL keeps order).
 */
import { DynamicResolution } from './dynamic-resolution.ts';
import { BAND_MS, bandRows, firstBandRows, grownBandRows, nextBandRows } from './frame-bands.ts';
import { GpuFence } from './gpu-fence.ts';
import { DEFAULT_SCALE_POLICY, scaledSize } from './render-scale.ts';
import type { Extent } from './resolve-pass.ts';

export interface FramePlan {
  /** The sample number: 0 starts the accumulation afresh. */
  readonly k: number;
  /** < 1: a preview, drawn into the preview target and stretched over the canvas. */
  readonly scale: number;
  /** The pixels of the target drawn (its first width × height). */
  readonly size: Extent;
  /** A band's GL rows [y0, y1) (the draw is scissored to them); null: the whole frame. */
  readonly rows: readonly [number, number] | null;
}

/** What the canvas shows: `base` resolved over all of it, then `over`'s rows at full size on top. */
export interface Shown {
  readonly base: 'preview' | 'accumulation';
  readonly samples: number;
  /** The part of the base target drawn (smaller than the canvas for a preview). */
  readonly size: Extent;
  /** The finished rows of a first full-size sample drawn over its preview, from the accumulation target. */
  readonly over: { readonly rows: readonly [number, number]; readonly samples: number } | null;
}

/** A band just finished: rows shown of the sample's height; `whole` when it was the last. */
export interface BandShown {
  readonly rows: number;
  readonly of: number;
  readonly whole: boolean;
}

/** The band sample in progress, for the test hooks: bands and rows shown so far, of its rows. */
export interface BandProgress {
  readonly bands: number;
  readonly rows: number;
  readonly of: number;
}

export interface StepContext {
  readonly is3d: boolean;
  /** The scene's sample count. */
  readonly target: number;
  /** The drawing buffer's size. */
  readonly width: number;
  readonly height: number;
  /** A program can draw (false while the scene does not compile: nothing is planned). */
  readonly drawable: boolean;
}

interface Band {
  readonly k: number;
  readonly size: Extent;
  /** Rows drawn and shown, from the top. */
  done: number;
  /** The next band's rows. */
  rows: number;
  bands: number;
  /** The band on the GPU now: its rows, when it was sent, and whether a poll found it unfinished. */
  sent: Sent | null;
}

interface Sent {
  readonly rows: number;
  readonly at: number;
  waited: boolean;
}

export class FrameSchedule {
  /** The 3D pane's frame timing and interactive scale. */
  readonly dynamic: DynamicResolution;
  private readonly inFlight = new GpuFence();
  private band: Band | null = null;
  /** The band size the last band measured, for the next sample of the same program and height. */
  private learned: { readonly height: number; readonly rows: number } | null = null;
  /** The next frame starts the accumulation afresh (until then the old picture stays). */
  private restartPending = true;
  /** Samples in the picture shown (a preview has one), its scale and drawn size. */
  private samplesDone = 0;
  private drawnScale = 1;
  private drawnSize: Extent = { width: 0, height: 0 };
  private lastBands = 1;
  /** The last interval between animation frames, and when the last one came (band timing). */
  private interval = 0;
  private lastStep = Number.NaN;

  constructor(
    private readonly bandMs: number = BAND_MS,
    private readonly clock: () => number = () => performance.now(),
  ) {
    this.dynamic = new DynamicResolution(DEFAULT_SCALE_POLICY, clock);
  }

  /** The picture changed (camera, value, size): interaction begins, and the picture restarts. */
  changed(now: number): void {
    this.dynamic.changed(now);
    this.restart();
  }

  /** The next frame starts afresh; a band sample in progress is dropped at once. */
  restart(): void {
    this.restartPending = true;
    this.band = null;
  }

  /** New generated code: its frame and band times are unknown. */
  newProgram(): void {
    this.dynamic.newProgram();
    this.learned = null;
  }

  /** Whether the next frame starts afresh (a restart is pending). */
  get restarting(): boolean {
    return this.restartPending;
  }

  /** Samples in the picture shown (a preview counts its one). */
  get samples(): number {
    return this.samplesDone;
  }

  /** Samples at full size on screen: 0 while a preview is shown. */
  get fullSamples(): number {
    return this.drawnScale < 1 ? 0 : this.samplesDone;
  }

  get scale(): number {
    return this.drawnScale;
  }

  get size(): Extent {
    return this.drawnSize;
  }

  /** The bands the last full sample was drawn in (1: whole). */
  get bands(): number {
    return this.lastBands;
  }

  get progress(): BandProgress | null {
    const b = this.band;
    return b && { bands: b.bands, rows: b.done, of: b.size.height };
  }

  /** The schedule's part of the viewport's stats (viewport-types.ts ViewportStats). */
  stats() {
    return {
      samples: this.fullSamples,
      renderScale: this.drawnScale,
      renderSize: { ...this.drawnSize },
      interactiveScale: this.dynamic.scale,
      bands: this.lastBands,
      band: this.progress,
    };
  }

  /** Whether frames are still wanted: a frame to draw, or a fence to poll. */
  wantsFrames(target: number, drawable: boolean): boolean {
    return (drawable && this.due(target)) || this.inFlight.pending || this.dynamic.measuring;
  }

  /** Milliseconds until a preview on screen is due at full size, else null. */
  refineIn(now: number): number | null {
    return this.drawnScale < 1 ? this.dynamic.settlesIn(now) : null;
  }

  /**
   * This animation frame's work: the band that finished since the last (to show) and the frame to
   * draw now, if any. While a band is on the GPU nothing else is planned.
   */
  step(
    gl: WebGL2RenderingContext,
    now: number,
    c: StepContext,
  ): { readonly finished: BandShown | null; readonly plan: FramePlan | null } {
    this.interval = Number.isFinite(this.lastStep) ? Math.max(0, now - this.lastStep) : 0;
    this.lastStep = now;
    const band = this.band;
    // An abandoned band's fence is polled only to know when the GPU is free (see `sent`).
    if (this.inFlight.waiting(gl) && band?.sent) {
      band.sent.waited = true;
      return { finished: null, plan: null };
    }
    const finished = band?.sent ? this.bandFinished(band, band.sent) : null;
    if (c.is3d) this.dynamic.poll(gl);
    const scale = c.is3d ? this.dynamic.frameScale(now) : 1;
    // A preview is drawn again at full size once the picture is still.
    if (this.drawnScale < 1 && scale === 1 && !this.band) this.restartPending = true;
    if (!c.drawable || !this.due(c.target)) return { finished, plan: null };
    return { finished, plan: this.plan(c, scale) };
  }

  /** The plan's draw calls were sent, starting at `start` (performance.now()). */
  sent(gl: WebGL2RenderingContext, plan: FramePlan, start: number, is3d: boolean): void {
    if (plan.rows && this.band) {
      this.band.sent = { rows: plan.rows[1] - plan.rows[0], at: start, waited: false };
      this.inFlight.set(gl);
      return;
    }
    this.samplesDone = plan.k + 1;
    this.drawnScale = plan.scale;
    this.drawnSize = plan.size;
    this.lastBands = 1;
    // Only whole frames are timed (the model needs them), and not one queued behind an abandoned band.
    if (is3d && !this.inFlight.pending) this.dynamic.end(gl, start, plan.scale);
  }

  /** What the canvas shows now (to present it, or read it back). */
  shown(): Shown {
    const b = this.band;
    if (b && b.done > 0) {
      const top = b.size.height;
      if (this.drawnScale < 1) {
        const over = { rows: [top - b.done, top] as const, samples: b.k + 1 };
        return { base: 'preview', samples: this.samplesDone, size: this.drawnSize, over };
      }
      // Over the last full-size picture: its rows keep their k samples, the finished ones have k + 1
      // (k = 0: the old picture's rows stay as they were). Alpha is 1 either way; colour is Σrgb / Σa.
      return { base: 'accumulation', samples: Math.max(1, b.k), size: b.size, over: null };
    }
    const base = this.drawnScale < 1 ? 'preview' : 'accumulation';
    return { base, samples: this.samplesDone, size: this.drawnSize, over: null };
  }

  /** The context was lost: every sync object went with it; the picture starts afresh. */
  forget(): void {
    this.inFlight.clear(null);
    this.dynamic.forget();
    this.restart();
  }

  dispose(gl: WebGL2RenderingContext): void {
    this.inFlight.clear(gl);
  }

  private due(target: number): boolean {
    return this.restartPending || this.band !== null || (this.samplesDone < target && this.drawnScale === 1);
  }

  private bandFinished(band: Band, sent: Sent): BandShown {
    band.sent = null;
    band.done += sent.rows;
    band.bands++;
    const of = band.size.height;
    // A band is seen finished only when a frame polls its fence: its measured time holds up to one
    // frame interval of waiting (hundreds of ms on a loaded machine), which is taken off. What is left
    // paces the next band (on SwiftShader the poll itself may block until the band is done: then
    // that is the band's time). A band with nothing left took under a frame: it grows, unless frames
    // come slowly anyway (a loaded machine), where it keeps its size.
    const own = this.clock() - sent.at - this.interval;
    if (own > 0) band.rows = nextBandRows(sent.rows, own, of, this.bandMs);
    else if (this.interval <= 2 * this.bandMs) band.rows = grownBandRows(sent.rows, of);
    else band.rows = sent.rows;
    this.learned = { height: of, rows: band.rows };
    const whole = band.done >= of;
    if (whole) {
      this.band = null;
      this.samplesDone = band.k + 1;
      this.drawnScale = 1;
      this.drawnSize = band.size;
      this.lastBands = band.bands;
    }
    return { rows: band.done, of, whole };
  }

  private plan(c: StepContext, scale: number): FramePlan {
    const k = this.band?.k ?? (this.restartPending ? 0 : this.samplesDone);
    this.restartPending = false;
    if (!this.band) {
      const size = scaledSize(c.width, c.height, scale);
      const rows = c.is3d && scale === 1 ? this.firstRows(size.height) : size.height;
      if (rows >= size.height) return { k, scale, size, rows: null };
      this.band = { k, size, done: 0, rows, bands: 0, sent: null };
    }
    const b = this.band;
    return { k: b.k, scale: 1, size: b.size, rows: bandRows(b.done, b.rows, b.size.height) };
  }

  /** The first band: from the preview's prediction, or what the last band measured when smaller. */
  private firstRows(height: number): number {
    const predicted = firstBandRows(this.dynamic.predictedMs(1), height, this.bandMs);
    const learned = this.learned?.height === height ? this.learned.rows : height;
    return Math.min(predicted, learned);
  }
}
