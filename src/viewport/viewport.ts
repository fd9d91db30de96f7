/**
 * The live picture: a Scene drawn into a canvas with progressive accumulation. One jittered sample
 * per animation frame while anything moves; once still, samples accumulate up to the scene's
 * `samples` and drawing stops (an idle page costs no GPU). Value edits reuse the linked program
 * (uniform upload only); after `idleBakeMs` without edits a baked program (values as literals,
 * several times faster) takes over until the next edit. Compile errors keep the last good frame on
 * screen and are reported with node ids. A lost WebGL context is rebuilt when the browser restores it.
 * A 3D scene is drawn at a reduced resolution while it changes (dynamic-resolution.ts) and again at
 * full size once still, in bands over several animation frames when one sample would be slow
 * (frame-bands.ts); a 2D scene always at full size, whole.
 */
import { sameCamera3d } from '../../nodes/core/camera-3d.ts';
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import { DEFAULT_VIEW, type View } from '../../nodes/core/view.ts';
import { sampleOffset } from '../../shader-gen/view.ts';
import { type Drawable, is3d } from './drawable.ts';
import { DynamicResolution } from './dynamic-resolution.ts';
import { BAND_MS, bandCount, bandRows } from './frame-bands.ts';
import { GpuFence } from './gpu-fence.ts';
import { liveMedia } from './live-media.ts';
import { refreshLive } from './live-textures.ts';
import { inspectCssPoint, type PixelInspection } from './pixel-probe.ts';
import { scaledSize } from './render-scale.ts';
import { createTarget, disposeTarget, type RenderTarget } from './render-target.ts';
import { Renderer } from './renderer.ts';
import { type SceneProgram, SceneProgramBuilder } from './scene-program.ts';
import { requestSrgbDrawingBuffer } from './srgb-canvas.ts';
import { renderTiled } from './tiled-render.ts';
import type { RenderToPixelsOptions, ViewportOptions, ViewportStats } from './viewport-types.ts';

export type { PixelInspection } from './pixel-probe.ts';
export type { RenderToPixelsOptions, ViewportOptions, ViewportStats } from './viewport-types.ts';

const CONTEXT_ATTRIBUTES: WebGLContextAttributes = {
  // An RGBA drawing buffer: only such a buffer can become SRGB8_ALPHA8 (srgb-canvas.ts). The
  // picture stays opaque: on screen u_bgAlpha is 1, so every resolved pixel has alpha 1.
  alpha: true,
  antialias: false,
  depth: false,
  stencil: false,
  preserveDrawingBuffer: false,
  powerPreference: 'high-performance',
};

export class Viewport {
  private readonly gl: WebGL2RenderingContext;
  private renderer: Renderer | null;
  private readonly programs: SceneProgramBuilder;
  private scene: Drawable | null = null;
  private explicitView: View | null = null;
  private explicitCamera: Camera3d | null = null;
  private sceneDirty = false;
  /** The program drawing now, or null while the scene does not compile (the last frame stays). */
  private active: SceneProgram | null = null;
  private accum: RenderTarget | null = null;
  private samplesDone = 0;
  /** The 3D pane's frame timing and interactive scale; the scale the picture on screen was drawn at. */
  private readonly dynamic = new DynamicResolution();
  private drawnScale = 1;
  private drawnSize = { width: 0, height: 0 };
  /** A full-size 3D sample being drawn band by band (frame-bands.ts): its index, the next band, how many. */
  private band: { readonly k: number; next: number; readonly count: number } | null = null;
  private lastBands = 1;
  /**
   * At most one band in flight: the frame loop does not wait for the GPU, so without this every band
   * would be queued at once and the GPU (and the page's compositor behind it) be as busy as with one
   * big draw. The next band is sent once the GPU has finished the last.
   */
  private readonly bandFence = new GpuFence();
  /** The next frame starts the accumulation afresh (until then the old picture stays). */
  private restartPending = true;
  /** When the previous frame was drawn, or when the change that restarts the picture came. */
  private frameClock = 0;
  /** When the first of the scenes not yet taken by a frame was set. */
  private sceneSetAt = 0;
  private framesDrawn = 0;
  private raf = 0;
  private wakeTimer: ReturnType<typeof setTimeout> | undefined;
  private lost = false;
  private disposed = false;
  private readonly idleBakeMs: number;
  private readonly detach: () => void;
  /** A live source (camera, video) feeds the program: frames are requested continuously. */
  private liveRunning = false;
  /** Live frames are held still while an export draws its tiles (one frame for the whole PNG). */
  private exporting = false;
  private liveUploads = 0;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly options: ViewportOptions = {},
  ) {
    const gl = canvas.getContext('webgl2', CONTEXT_ATTRIBUTES);
    if (!gl) throw new Error('WebGL2 is not available in this browser');
    this.gl = gl;
    requestSrgbDrawingBuffer(gl, canvas.width, canvas.height);
    this.idleBakeMs = options.idleBakeMs ?? 600;
    this.renderer = new Renderer(gl, () => this.restart());
    this.programs = new SceneProgramBuilder((d) => options.onDiagnostics?.(d));
    const onLost = (e: Event) => {
      e.preventDefault(); // tells the browser we want the context back
      this.lost = true;
      this.stopLoop();
      this.programs.forget(this.renderer);
      this.renderer = null; // every GL object died with the context
      this.accum = null;
      this.active = null;
      this.restartPending = true;
      this.band = null;
      this.bandFence.clear(null);
      this.dynamic.forget();
    };
    const onRestored = () => {
      try {
        this.renderer = new Renderer(gl, () => this.restart());
        requestSrgbDrawingBuffer(gl, canvas.width, canvas.height);
      } catch (e) {
        // Lost again while rebuilding: the next 'webglcontextrestored' tries once more.
        console.warn('[kleinflow] could not rebuild the WebGL renderer', e);
        return;
      }
      this.lost = false;
      this.sceneDirty = this.scene !== null;
      this.requestFrame();
    };
    canvas.addEventListener('webglcontextlost', onLost);
    canvas.addEventListener('webglcontextrestored', onRestored);
    // A source starting or failing changes what is bound (its frames or its fallback).
    const unsubscribe = liveMedia.subscribe(() => this.restart());
    this.detach = () => {
      unsubscribe();
      canvas.removeEventListener('webglcontextlost', onLost);
      canvas.removeEventListener('webglcontextrestored', onRestored);
    };
  }

  get stats(): ViewportStats {
    return {
      compiles: this.programs.compiles(this.renderer),
      bakedCompiles: this.programs.bakedCompiles(this.renderer),
      frames: this.framesDrawn,
      samples: this.drawnScale < 1 ? 0 : this.samplesDone,
      baked: this.active?.baked ?? false,
      liveUploads: this.liveUploads,
      renderScale: this.drawnScale,
      renderSize: { ...this.drawnSize },
      interactiveScale: this.dynamic.scale,
      bands: this.lastBands,
    };
  }

  /**
   * Recompiles only when the generated source changes (else uploads uniforms) and restarts
   * accumulation; a scene with the same source and values as the current one changes nothing.
   * A 3D scene (Scene3d) is drawn through the camera of setCamera (else its own).
   */
  setScene(scene: Drawable): void {
    if (!this.sceneDirty) this.sceneSetAt = performance.now();
    this.scene = scene;
    this.sceneDirty = true;
    this.requestFrame();
  }

  /** The scene drawn now (2D or 3D), or null before the first. */
  drawing(): Drawable | null {
    return this.scene;
  }

  /**
   * The 3D view's camera (a frame uniform, like the 2D view): restarts accumulation; never compiles.
   * The same camera again changes nothing (a 3D frame is too dear to redraw for nothing).
   */
  setCamera(camera: Camera3d): void {
    const same = this.explicitCamera !== null && sameCamera3d(this.explicitCamera, camera);
    this.explicitCamera = camera;
    if (!same) this.restart();
  }

  /** Restarts accumulation (not of a 3D scene, which has no 2D view); never compiles. */
  setView(view: View): void {
    this.explicitView = view;
    if (!this.scene || !is3d(this.scene)) this.restart();
  }

  setSize(width: number, height: number, dpr = globalThis.devicePixelRatio || 1): void {
    const w = Math.max(1, Math.round(width * dpr));
    const h = Math.max(1, Math.round(height * dpr));
    if (this.canvas.width !== w) this.canvas.width = w;
    if (this.canvas.height !== h) this.canvas.height = h;
    requestSrgbDrawingBuffer(this.gl, w, h);
    this.canvas.style.width = `${width}px`;
    this.canvas.style.height = `${height}px`;
    this.restart();
  }

  /**
   * The picture at any size, offscreen and tiled, with the full sample count: RGBA 8-bit sRGB,
   * top row first; null when onProgress returned false. Uses the baked program when it builds.
   */
  async renderToPixels(opts: RenderToPixelsOptions): Promise<Uint8ClampedArray | null> {
    const scene = opts.scene ?? this.scene;
    if (!scene) throw new Error('renderToPixels: no scene was set');
    const renderer = this.requireRenderer();
    const program = this.programs.exportProgram(renderer, scene);
    await renderer.pictures.whenReady(program.pictures);
    // The live sources' current frame, held for every tile.
    this.refreshLiveFrames(renderer, program.pictures);
    this.exporting = true;
    try {
      return await renderTiled(
        () => this.requireRenderer(),
        () => program,
        {
          width: opts.width,
          height: opts.height,
          samples: opts.samples,
          view: opts.view ?? this.view(scene),
          camera: this.camera(scene, opts.camera),
          transparent: opts.transparent ?? false,
          tile: opts.tile,
          onProgress: opts.onProgress,
        },
      );
    } finally {
      this.exporting = false;
    }
  }

  /** The picture on the canvas now (resolved from the accumulation buffer), top row first; null before the first frame. */
  snapshot(): Uint8ClampedArray | null {
    const r = this.renderer;
    if (!r || !this.accum || this.samplesDone === 0) return null;
    const { width, height } = this.accum;
    const scratch = createTarget(r.gl, width, height, 'srgb8');
    try {
      return r.readResolved(this.accum, this.samplesDone, scratch, width, height, this.drawnSize);
    } finally {
      disposeTarget(r.gl, scratch);
    }
  }

  /** "Explain this pixel" at a CSS point of the canvas (pixel-probe.ts); null before a 2D scene is set. */
  inspectAt(cssX: number, cssY: number): PixelInspection | null {
    const scene = this.scene;
    if (!scene || is3d(scene)) return null;
    return inspectCssPoint(this.renderer, this.canvas, scene, this.view(scene), { x: cssX, y: cssY });
  }

  dispose(): void {
    this.disposed = true;
    this.stopLoop();
    this.detach();
    if (this.renderer) {
      this.bandFence.clear(this.gl);
      disposeTarget(this.gl, this.accum);
      this.renderer.dispose();
    }
    this.renderer = null;
    this.accum = null;
    this.active = null;
  }

  /** The 2D view; a 3D program has no u_view (it has a camera), so any view serves. */
  private view(scene: Drawable): View {
    return is3d(scene) ? DEFAULT_VIEW : (this.explicitView ?? scene.view);
  }

  /** The camera a 3D scene is drawn through: the one asked for, the view's, else the scene's. */
  private camera(scene: Drawable, asked?: Camera3d): Camera3d | undefined {
    return is3d(scene) ? (asked ?? this.explicitCamera ?? scene.camera) : undefined;
  }

  private requireRenderer(): Renderer {
    if (this.disposed) throw new Error('the viewport was disposed');
    if (!this.renderer) throw new Error('the WebGL context is lost');
    return this.renderer;
  }

  /** Uploads the live sources' new frames (none while exporting); true when the picture changed. */
  private refreshLiveFrames(renderer: Renderer, pictures: readonly string[]): boolean {
    if (this.exporting) return false;
    const r = refreshLive(renderer.pictures.live, pictures, (id) => liveMedia.frameOf(id));
    this.liveRunning = r.running;
    if (r.changed) this.liveUploads++;
    return r.changed;
  }

  private restart(): void {
    this.dynamic.changed(performance.now());
    if (!this.restartPending) this.frameClock = performance.now();
    this.restartPending = true;
    this.requestFrame();
  }

  private requestFrame(): void {
    if (this.raf !== 0 || this.lost || this.disposed) return;
    clearTimeout(this.wakeTimer);
    this.wakeTimer = undefined;
    this.raf = requestAnimationFrame((now) => this.tick(now));
  }

  private stopLoop(): void {
    if (this.raf !== 0) cancelAnimationFrame(this.raf);
    this.raf = 0;
    clearTimeout(this.wakeTimer);
    this.wakeTimer = undefined;
  }

  private tick(now: number): void {
    this.raf = 0;
    const renderer = this.renderer;
    const scene = this.scene;
    if (!renderer || !scene || this.lost || this.disposed) return;
    if (this.sceneDirty) {
      this.sceneDirty = false;
      const change = this.programs.apply(renderer, scene, now);
      if (change !== 'same' || !this.active) {
        // A scene that does not compile leaves active null: nothing is drawn, the last frame stays.
        this.active = this.programs.current();
        this.dynamic.changed(now);
        if (change === 'code') this.dynamic.newProgram();
        if (!this.restartPending) this.frameClock = this.sceneSetAt;
        this.restartPending = true;
      }
    }
    const baked = this.programs.pollBake(renderer, scene, now, this.idleBakeMs);
    if (baked) this.active = baked;
    if (this.active && this.refreshLiveFrames(renderer, this.active.pictures)) this.restartPending = true;
    const target = Math.max(1, scene.samples);
    const scale = this.frameScale(scene, now);
    // A reduced picture is a preview: once still, it is drawn again at full size (maybe in bands).
    if (this.drawnScale < 1 && scale === 1 && !this.band) this.restartPending = true;
    // While the GPU draws a band nothing else is submitted.
    const waiting = this.bandFence.waiting(this.gl);
    const due = this.restartPending || this.band || (this.samplesDone < target && this.drawnScale === 1);
    if (!waiting && this.active && due) {
      this.drawFrame(renderer, this.active, scene, target, scale);
    }
    this.schedule(now, target);
  }

  /** Full size for 2D; for 3D the dynamic scale (timing the frames that finished meanwhile). */
  private frameScale(scene: Drawable, now: number): number {
    if (!is3d(scene)) return 1;
    this.dynamic.poll(this.gl);
    return this.dynamic.frameScale(now);
  }

  private drawFrame(
    renderer: Renderer,
    program: SceneProgram,
    scene: Drawable,
    target: number,
    scale: number,
  ): void {
    // The drawing buffer can be smaller than canvas.width × height (browsers cap its size).
    const width = this.gl.drawingBufferWidth;
    const height = this.gl.drawingBufferHeight;
    if (!this.accum || this.accum.width !== width || this.accum.height !== height) {
      disposeTarget(this.gl, this.accum);
      this.accum = createTarget(this.gl, width, height, 'accumulation');
      this.restartPending = true;
    }
    // A change abandons a sample drawn in bands: the next one starts afresh.
    if (this.restartPending) this.band = null;
    const k = this.band?.k ?? (this.restartPending ? 0 : this.samplesDone);
    this.restartPending = false;
    // A reduced frame fills the accumulation buffer's corner and is stretched over the canvas.
    const drawn = scaledSize(width, height, scale);
    if (!this.band) {
      const slow = is3d(scene) && scale === 1 ? this.dynamic.predictedMs(1) : 0;
      this.band = { k, next: 0, count: bandCount(slow, drawn.height, this.options.bandMs ?? BAND_MS) };
    }
    const band = this.band;
    const frame = {
      width: drawn.width,
      height: drawn.height,
      offsetX: 0,
      offsetY: 0,
      view: this.view(scene),
      camera: this.camera(scene),
      jitter: sampleOffset(k),
      bgAlpha: 1,
    };
    const start = this.dynamic.begin();
    const { gp, uniforms, pictures } = program;
    const banded = band.count > 1;
    if (banded) {
      // This band's rows only (a scissored clear and draw); the canvas keeps the last whole sample.
      const [y0, y1] = bandRows(band.next, band.count, drawn.height);
      this.gl.enable(this.gl.SCISSOR_TEST);
      this.gl.scissor(0, y0, drawn.width, y1 - y0);
    }
    renderer.drawSample(gp, uniforms, this.accum, drawn.width, drawn.height, frame, k, pictures);
    if (banded) {
      this.gl.disable(this.gl.SCISSOR_TEST);
      this.bandFence.set(this.gl);
    }
    band.next++;
    if (band.next < band.count) return;
    this.band = null;
    this.lastBands = band.count;
    this.samplesDone = k + 1;
    this.drawnScale = scale;
    this.drawnSize = drawn;
    renderer.present(this.accum, this.samplesDone, width, height, drawn);
    // Only a sample drawn whole is timed (the model needs whole frames).
    if (is3d(scene) && band.count === 1) this.dynamic.end(this.gl, start, scale);
    this.framesDrawn++;
    const now = performance.now();
    const samples = scale < 1 ? 0 : this.samplesDone;
    this.options.onFrame?.({ samples, target, ms: now - this.frameClock, scale });
    this.frameClock = now;
  }

  /** Keeps the loop running while there is work; sleeps (no frames at all) until the bake is due. */
  private schedule(now: number, target: number): void {
    const more =
      this.restartPending || this.band !== null || (this.samplesDone < target && this.drawnScale === 1);
    const drawing = this.active !== null && more;
    // A timed 3D frame is polled each animation frame until its fence is signalled.
    if (
      this.sceneDirty ||
      drawing ||
      this.liveRunning ||
      this.bandFence.pending ||
      this.programs.bakeInFlight() ||
      this.dynamic.measuring
    ) {
      this.requestFrame();
      return;
    }
    const bake = this.programs.bakeDueIn(now, this.idleBakeMs);
    const refine = this.drawnScale < 1 ? this.dynamic.settlesIn(now) : null;
    const due = bake === null ? refine : refine === null ? bake : Math.min(bake, refine);
    if (due !== null) this.wakeTimer = setTimeout(() => this.requestFrame(), due);
  }
}

export { attachPanZoom } from './pan-zoom.ts';
