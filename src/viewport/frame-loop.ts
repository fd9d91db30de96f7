/**
 * The live picture's animation-frame loop: at most one frame requested at a time, and a timer that
 * wakes it later (an idle bake, a preview due at full size) so that an idle page requests no frames
 * at all.
 */
export class FrameLoop {
  private raf = 0;
  private wakeTimer: ReturnType<typeof setTimeout> | undefined;

  constructor(private readonly tick: (now: number) => void) {}

  /** Requests the next animation frame (once; a pending wake-up is superseded). */
  request(): void {
    if (this.raf !== 0) return;
    this.clearWake();
    this.raf = requestAnimationFrame((now) => {
      this.raf = 0;
      this.tick(now);
    });
  }

  /** Requests a frame in `ms` milliseconds. */
  wakeIn(ms: number): void {
    this.clearWake();
    this.wakeTimer = setTimeout(() => this.request(), ms);
  }

  stop(): void {
    if (this.raf !== 0) cancelAnimationFrame(this.raf);
    this.raf = 0;
    this.clearWake();
  }

  private clearWake(): void {
    clearTimeout(this.wakeTimer);
    this.wakeTimer = undefined;
  }
}
