/**
 * A WebGL context can be taken away at any time (GPU reset, driver update, too many contexts on the
 * page) and every GL object dies with it. The browser gives it back only if the loss event is
 * cancelled, and the rebuild can fail when the context is lost again meanwhile (the next restore
 * event tries again). Those rules live here so that the viewport says only what to drop, how to
 * rebuild and how to go on.
 */

export interface ContextLife {
  /** The context is gone: drop every GL object (no GL call can succeed now). */
  drop(): void;
  /** The context is back: make the GL objects again; may throw (lost again meanwhile). */
  rebuild(): void;
  /** The rebuild worked and `lost` is false again: draw. */
  resume(): void;
}

export class ContextLoss {
  private lostNow = false;
  private readonly detach: () => void;

  constructor(canvas: HTMLCanvasElement, life: ContextLife) {
    const onLost = (e: Event) => {
      e.preventDefault(); // tells the browser we want the context back
      this.lostNow = true;
      life.drop();
    };
    const onRestored = () => {
      try {
        life.rebuild();
      } catch (e) {
        // Lost again while rebuilding: the next 'webglcontextrestored' tries once more.
        console.warn('[kleinflow] could not rebuild the WebGL renderer', e);
        return;
      }
      this.lostNow = false;
      life.resume();
    };
    canvas.addEventListener('webglcontextlost', onLost);
    canvas.addEventListener('webglcontextrestored', onRestored);
    this.detach = () => {
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
    };
  }

  /** Between a loss and a successful rebuild: nothing may be drawn. */
  get lost(): boolean {
    return this.lostNow;
  }

  dispose(): void {
    this.detach();
  }
}
