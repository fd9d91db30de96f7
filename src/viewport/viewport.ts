/**
 * The live picture: a Scene drawn into a canvas with progressive accumulation. One jittered sample
 * per animation frame while anything moves; once still, samples accumulate up to the scene's
 * `samples` and drawing stops (an idle page costs no GPU). Value edits reuse the linked program
 * (uniform upload only); after `idleBakeMs` without edits a baked program (values as literals,
 * several times faster) takes over until the next edit. Compile errors keep the last good frame on
 * screen and are reported with node ids. A lost WebGL context is rebuilt when the browser restores it
 * (context-loss.ts); live sources keep the loop running while they play (live-feed.ts).
 * Which sample, at which scale, whole or in bands, is frame-schedule.ts's to say: a 3D scene is
 * previewed at a reduced resolution while it changes and drawn again at full size once still, band
 * by band over the preview when one sample would be slow; a 2D scene always at full size, whole.
 */
import { sameCamera3d } from '../../nodes/core/camera-3d.ts';
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import { DEFAULT_VIEW, type View } from '../../nodes/core/view.ts';
import { sampleOffset } from '../../shader-gen/view.ts';
import { ContextLoss } from './context-loss.ts';
import { type Drawable, is3d } from './drawable.ts';
import { BAND_MS } from './frame-bands.ts';
import { FrameLoop } from './frame-loop.ts';
import { type FramePlan, FrameSchedule } from './frame-schedule.ts';
import { LiveFeed } from './live-feed.ts';
import { PaneTargets } from './pane-targets.ts';
import { inspectCssPoint, type PixelInspection } from './pixel-probe.ts';
import { Renderer } from './renderer.ts';
import { type SceneProgram, SceneProgramBuilder } from './scene-program.ts';
import { openSrgbCanvas, requestSrgbDrawingBuffer, sizeSrgbCanvas } from './srgb-canvas.ts';
import { renderTiled } from './tiled-render.ts';
import type { RenderToPixelsOptions, ViewportOptions, ViewportStats } from './viewport-types.ts';

export type { PixelInspection } from './pixel-probe.ts';
export type { RenderToPixelsOptions, ViewportOptions, ViewportStats } from './viewport-types.ts';

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
  private readonly targets: PaneTargets;
  private readonly frames: FrameSchedule;
  /** When the previous frame was drawn, or when the change that restarts the picture came. */
  private frameClock = 0;
  /** When the first of the scenes not yet taken by a frame was set. */
  private sceneSetAt = 0;
  private framesDrawn = 0;
  private readonly loop = new FrameLoop((now) => this.tick(now));
  private disposed = false;
  private readonly idleBakeMs: number;
  private readonly context: ContextLoss;
  private readonly live: LiveFeed;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly options: ViewportOptions = {},
  ) {
    const gl = openSrgbCanvas(canvas);
    this.gl = gl;
    this.idleBakeMs = options.idleBakeMs ?? 600;
    this.frames = new FrameSchedule(options.bandMs ?? BAND_MS);
    this.targets = new PaneTargets(gl);
    this.renderer = new Renderer(gl, () => this.restart());
    this.programs = new SceneProgramBuilder((d) => options.onDiagnostics?.(d));
    this.context = new ContextLoss(canvas, {
      drop: () => {
        this.loop.stop();
        this.programs.forget(this.renderer);
        this.renderer = null; // every GL object died with the context
        this.targets.forget();
        this.active = null;
        this.frames.forget();
      },
      rebuild: () => {
        this.renderer = new Renderer(gl, () => this.restart());
        requestSrgbDrawingBuffer(gl, canvas.width, canvas.height);
      },
      resume: () => {
        this.sceneDirty = this.scene !== null;
        this.requestFrame();
      },
    });
    this.live = new LiveFeed(() => this.restart());
  }

  get stats(): ViewportStats {
    return {
      compiles: this.programs.compiles(this.renderer),
      bakedCompiles: this.programs.bakedCompiles(this.renderer),
      frames: this.framesDrawn,
      baked: this.active?.baked ?? false,
      liveUploads: this.live.uploads,
      ...this.frames.stats(),
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
    sizeSrgbCanvas(this.gl, this.canvas, width, height, dpr);
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
    const view = opts.view ?? this.view(scene);
    const camera = this.camera(scene, opts.camera);
    const tiled = { ...opts, view, camera, transparent: opts.transparent ?? false };
    const draw = () =>
      renderTiled(
        () => this.requireRenderer(),
        () => program,
        tiled,
      );
    return this.live.holdDuring(renderer.pictures.live, program.pictures, draw);
  }

  /** The picture on the canvas now (resolved from the accumulation buffer), top row first; null before the first frame. */
  snapshot(): Uint8ClampedArray | null {
    return this.renderer && this.targets.read(this.renderer, this.frames.shown());
  }

  /** "Explain this pixel" at a CSS point of the canvas (pixel-probe.ts); null before a 2D scene is set. */
  inspectAt(cssX: number, cssY: number): PixelInspection | null {
    const scene = this.scene;
    if (!scene || is3d(scene)) return null;
    return inspectCssPoint(this.renderer, this.canvas, scene, this.view(scene), { x: cssX, y: cssY });
  }

  dispose(): void {
    this.disposed = true;
    this.loop.stop();
    this.live.dispose();
    this.context.dispose();
    if (this.renderer) {
      this.frames.dispose(this.gl);
      this.targets.dispose();
      this.renderer.dispose();
    }
    this.renderer = null;
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

  private restart(): void {
    if (!this.frames.restarting) this.frameClock = performance.now();
    this.frames.changed(performance.now());
    this.requestFrame();
  }

  private requestFrame(): void {
    if (!this.context.lost && !this.disposed) this.loop.request();
  }

  private tick(now: number): void {
    const renderer = this.renderer;
    const scene = this.scene;
    if (!renderer || !scene || this.context.lost || this.disposed) return;
    if (this.sceneDirty) {
      this.sceneDirty = false;
      const change = this.programs.apply(renderer, scene, now);
      if (change !== 'same' || !this.active) {
        // A scene that does not compile leaves active null: nothing is drawn, the last frame stays.
        this.active = this.programs.current();
        if (!this.frames.restarting) this.frameClock = this.sceneSetAt;
        this.frames.changed(now);
        if (change === 'code') this.frames.newProgram();
      }
    }
    const baked = this.programs.pollBake(renderer, scene, now, this.idleBakeMs);
    if (baked) this.active = baked;
    if (this.active && this.live.refresh(renderer.pictures.live, this.active.pictures)) this.frames.restart();
    const target = Math.max(1, scene.samples);
    if (this.targets.fit()) this.frames.restart();
    const { width, height } = this.targets;
    const context = { is3d: is3d(scene), target, width, height, drawable: this.active !== null };
    const { finished, plan } = this.frames.step(this.gl, now, context);
    // The next band goes first: its fence (its timing) must not wait for the whole-canvas present.
    const band = plan?.rows && this.active ? this.active : null;
    if (band && plan) this.drawFrame(renderer, band, scene, plan, target);
    if (finished) {
      this.present(renderer);
      if (finished.whole) this.frameDone(target);
      else this.options.onBand?.({ rows: finished.rows, of: finished.of, samples: this.frames.fullSamples });
    }
    if (plan && this.active && !band) this.drawFrame(renderer, this.active, scene, plan, target);
    this.keepRunning(now, target);
  }

  private drawFrame(
    renderer: Renderer,
    program: SceneProgram,
    scene: Drawable,
    plan: FramePlan,
    target: number,
  ): void {
    const frame = {
      ...plan.size,
      offsetX: 0,
      offsetY: 0,
      view: this.view(scene),
      camera: this.camera(scene),
      jitter: sampleOffset(plan.k),
      bgAlpha: 1,
    };
    const start = performance.now();
    this.targets.draw(renderer, program, plan, frame);
    this.frames.sent(this.gl, plan, start, is3d(scene));
    // A band is shown once the GPU has finished it (step's `finished`); a whole frame at once.
    if (plan.rows) return;
    this.present(renderer);
    this.frameDone(target);
  }

  private present(renderer: Renderer): void {
    this.targets.present(renderer, this.frames.shown());
  }

  /** A whole sample is on screen: counted and reported. */
  private frameDone(target: number): void {
    this.framesDrawn++;
    const now = performance.now();
    const scale = this.frames.scale;
    this.options.onFrame?.({ samples: this.frames.fullSamples, target, ms: now - this.frameClock, scale });
    this.frameClock = now;
  }

  /** Keeps the loop running while there is work; sleeps (no frames at all) until the bake is due. */
  private keepRunning(now: number, target: number): void {
    const busy = this.sceneDirty || this.live.running || this.programs.bakeInFlight();
    if (busy || this.frames.wantsFrames(target, this.active !== null)) {
      this.requestFrame();
      return;
    }
    const bake = this.programs.bakeDueIn(now, this.idleBakeMs);
    const refine = this.frames.refineIn(now);
    const due = bake === null ? refine : refine === null ? bake : Math.min(bake, refine);
    if (due !== null) this.loop.wakeIn(due);
  }
}

export { attachPanZoom } from './pan-zoom.ts';
