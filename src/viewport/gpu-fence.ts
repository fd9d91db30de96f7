/**
 * One GPU fence, polled without waiting: the viewport's way to know that the GPU has finished the
 * commands sent so far (a frame being timed, dynamic-resolution.ts; a band in flight,
 * frame-bands.ts) without a `readPixels` stall.
 */
export class GpuFence {
  private sync: WebGLSync | null = null;

  /** Marks the commands sent so far and flushes them (a fence never flushed is never signalled); false when no fence could be made. */
  set(gl: WebGL2RenderingContext): boolean {
    this.clear(gl);
    this.sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (!this.sync) return false;
    gl.flush();
    return true;
  }

  /** Whether a fence is set and the GPU has not reached it yet; once reached, the fence is gone. */
  waiting(gl: WebGL2RenderingContext): boolean {
    if (!this.sync) return false;
    if (gl.getSyncParameter(this.sync, gl.SYNC_STATUS) !== gl.SIGNALED) return true;
    this.clear(gl);
    return false;
  }

  get pending(): boolean {
    return this.sync !== null;
  }

  /** Deletes the fence (pass null after a lost context: the fence died with it). */
  clear(gl: WebGL2RenderingContext | null): void {
    if (this.sync && gl) gl.deleteSync(this.sync);
    this.sync = null;
  }
}
