/**
 * The GL side of the 3D pane's dynamic resolution (policy: render-scale.ts). Times frames with a
 * fence: the time from submitting a frame to its fence being signalled, seen by polling once per
 * animation frame (so it is rounded up to the display's frame interval, which only matters for
 * frames that are fast anyway). One frame is timed at a time, so a measurement never includes a
 * queue of earlier frames. Keeps the interactive scale and when the picture last changed.
 */
import { GpuFence } from './gpu-fence.ts';
import { DEFAULT_SCALE_POLICY, interacting, nextRenderScale, type ScalePolicy } from './render-scale.ts';

interface Timing {
  readonly fence: GpuFence;
  readonly start: number;
  readonly scale: number;
  /** The program generation it timed (newProgram): an older one's time is not this program's. */
  readonly generation: number;
}

export class DynamicResolution {
  /** The scale of frames drawn while the user interacts (1 until a frame proves too slow). */
  private interactiveScale = 1;
  private timing: Timing | null = null;
  private lastChangeAt = Number.NEGATIVE_INFINITY;
  /** The latest measured frame, for the test hooks and the status line, and the scale it had. */
  lastFrameMs = 0;
  private lastScale = 1;
  private generation = 0;

  constructor(
    private readonly policy: ScalePolicy = DEFAULT_SCALE_POLICY,
    /** The time in ms (performance.now; tests pass their own, so a timing never reads the real clock). */
    private readonly clock: () => number = () => performance.now(),
  ) {}

  /** The picture changed (camera, value, size): interaction until `settleMs` of stillness. */
  changed(now: number): void {
    this.lastChangeAt = now;
  }

  /**
   * The scale to draw a frame at now: reduced while interacting, 1 once still — but before a frame
   * of this program was timed, the smallest scale: a cheap first frame whose time predicts the
   * full-size one (which frame-bands.ts then splits when it is slow), never a blind full-size draw.
   */
  frameScale(now: number): number {
    if (this.lastFrameMs === 0) return this.policy.minScale;
    return interacting(now - this.lastChangeAt, this.policy) ? this.interactiveScale : 1;
  }

  /** A new program (new generated code): its frame times are unknown until one is timed. */
  newProgram(): void {
    this.lastFrameMs = 0;
    this.lastScale = 1;
    this.generation++;
  }

  /** Milliseconds until the picture counts as still (0: it does). */
  settlesIn(now: number): number {
    return Math.max(0, this.lastChangeAt + this.policy.settleMs - now);
  }

  /** Whether a timed frame has not finished yet (the caller keeps polling). */
  get measuring(): boolean {
    return this.timing !== null;
  }

  /** Call right before a frame's draw calls; returns the start time for `end`. */
  begin(): number {
    return this.clock();
  }

  /** Call after a frame's draw calls: times it unless another timed frame is still running. */
  end(gl: WebGL2RenderingContext, start: number, scale: number): void {
    if (this.timing) return;
    const fence = new GpuFence();
    if (!fence.set(gl)) return;
    this.timing = { fence, start, scale, generation: this.generation };
  }

  /** Takes a finished timing into the interactive scale; never waits for the GPU. */
  poll(gl: WebGL2RenderingContext): void {
    const t = this.timing;
    if (!t || t.fence.waiting(gl)) return;
    const ms = this.clock() - t.start;
    this.timing = null;
    if (t.generation !== this.generation) return;
    this.lastFrameMs = ms;
    this.lastScale = t.scale;
    this.interactiveScale = nextRenderScale(this.interactiveScale, { ms, scale: t.scale }, this.policy);
  }

  /** The predicted time of a frame at `scale` from the latest measured one (render-scale.ts model); 0 before any. */
  predictedMs(scale: number): number {
    return this.lastFrameMs > 0 ? this.lastFrameMs * (scale / this.lastScale) ** 2 : 0;
  }

  /** The context was lost: its sync object went with it. */
  forget(): void {
    this.timing = null;
  }

  get scale(): number {
    return this.interactiveScale;
  }
}
