/**
 * The viewport's side of the live sources (camera, video): unlike every other input they change
 * with no edit at all, so the frame loop must ask each frame whether one has a new frame, keep
 * running while any runs, and hear when one starts or fails (its frames replace the fallback, or
 * the other way round). An export holds them still so that every tile of the PNG shows one frame.
 * live-media.ts owns the page's media, live-textures.ts the textures; this only connects them to
 * the loop.
 */
import { liveMedia } from './live-media.ts';
import { type LiveTextures, refreshLive } from './live-textures.ts';

export class LiveFeed {
  private runningNow = false;
  private held = false;
  private uploadCount = 0;
  private readonly unsubscribe: () => void;

  /** `onChange`: a source started or failed, so what the program samples changed. */
  constructor(onChange: () => void) {
    this.unsubscribe = liveMedia.subscribe(onChange);
  }

  /** Whether a source the program samples ran at the last refresh (frames are wanted continuously). */
  get running(): boolean {
    return this.runningNow;
  }

  /** Frames uploaded so far (ViewportStats.liveUploads). */
  get uploads(): number {
    return this.uploadCount;
  }

  /** Uploads the new frames of the live keys among `pictures` (none while held); true when the picture changed. */
  refresh(textures: LiveTextures, pictures: readonly string[]): boolean {
    if (this.held) return false;
    const r = refreshLive(textures, pictures, (id) => liveMedia.frameOf(id));
    this.runningNow = r.running;
    if (r.changed) this.uploadCount++;
    return r.changed;
  }

  /**
   * Runs `draw` (an export) on the sources' current frame, held still until it ends: the export
   * yields to the page between samples, where the loop goes on refreshing, and every tile of the PNG
   * must show the same frame.
   */
  async holdDuring<T>(
    textures: LiveTextures,
    pictures: readonly string[],
    draw: () => Promise<T>,
  ): Promise<T> {
    this.refresh(textures, pictures);
    this.held = true;
    try {
      return await draw();
    } finally {
      this.held = false;
    }
  }

  dispose(): void {
    this.unsubscribe();
  }
}
