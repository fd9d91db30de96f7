/**
 * The live picture's offscreen targets: the accumulation target at the drawing buffer's size and,
 * apart from it, the target of the 3D previews, so that the first full-size sample can be drawn
 * band by band into the first while the canvas still shows the second under the finished rows
 * (frame-schedule.ts `shown`). Both die with a lost context and are made again when next needed.
 */
import type { FramePlan, Shown } from './frame-schedule.ts';
import { createTarget, disposeTarget, type RenderTarget } from './render-target.ts';
import type { Layer, Renderer } from './renderer.ts';
import type { SceneProgram } from './scene-program.ts';
import type { FrameParams } from './uniforms.ts';

export class PaneTargets {
  private accum: RenderTarget | null = null;
  private preview: RenderTarget | null = null;

  constructor(private readonly gl: WebGL2RenderingContext) {}

  /**
   * Makes the accumulation target the drawing buffer's size (it can be smaller than canvas.width ×
   * height: browsers cap it); true when it is new (the picture restarts).
   */
  fit(): boolean {
    const width = this.gl.drawingBufferWidth;
    const height = this.gl.drawingBufferHeight;
    if (this.accum?.width === width && this.accum.height === height) return false;
    disposeTarget(this.gl, this.accum);
    this.accum = createTarget(this.gl, width, height, 'accumulation');
    return true;
  }

  /** The accumulation target's size (0 × 0 before `fit`). */
  get width(): number {
    return this.accum?.width ?? 0;
  }

  get height(): number {
    return this.accum?.height ?? 0;
  }

  /** Draws the plan's sample: a preview into its own target, else into the accumulation (a band: its rows). */
  draw(renderer: Renderer, program: SceneProgram, plan: FramePlan, frame: FrameParams): void {
    const into = plan.scale < 1 ? this.previewTarget() : this.accum;
    if (!into) return;
    const gl = this.gl;
    const { width, height } = plan.size;
    if (plan.rows) {
      // This band's rows only (a scissored clear and draw).
      const [y0, y1] = plan.rows;
      gl.enable(gl.SCISSOR_TEST);
      gl.scissor(0, y0, width, y1 - y0);
    }
    renderer.drawSample(program.gp, program.uniforms, into, width, height, frame, plan.k, program.pictures);
    if (plan.rows) gl.disable(gl.SCISSOR_TEST);
  }

  present(renderer: Renderer, shown: Shown): void {
    const layers = this.layers(shown);
    if (layers) renderer.present(layers.base, this.width, this.height, layers.over);
  }

  /** The picture `shown` describes, top row first; null before there is one. */
  read(renderer: Renderer, shown: Shown): Uint8ClampedArray | null {
    const layers = this.layers(shown);
    if (!layers || shown.samples === 0) return null;
    const scratch = createTarget(this.gl, this.width, this.height, 'srgb8');
    try {
      return renderer.readResolved(layers.base, scratch, this.width, this.height, layers.over);
    } finally {
      disposeTarget(this.gl, scratch);
    }
  }

  /** The context was lost: the targets went with it. */
  forget(): void {
    this.accum = null;
    this.preview = null;
  }

  dispose(): void {
    disposeTarget(this.gl, this.accum);
    disposeTarget(this.gl, this.preview);
    this.forget();
  }

  /** The preview target, as large as the accumulation one (a preview fills its corner). */
  private previewTarget(): RenderTarget | null {
    const accum = this.accum;
    if (!accum) return null;
    if (this.preview?.width !== accum.width || this.preview.height !== accum.height) {
      disposeTarget(this.gl, this.preview);
      this.preview = createTarget(this.gl, accum.width, accum.height, 'accumulation');
    }
    return this.preview;
  }

  private layers(s: Shown): { base: Layer; over?: Layer } | null {
    const base = s.base === 'preview' ? this.preview : this.accum;
    if (!base || !this.accum) return null;
    const over = s.over ? { target: this.accum, samples: s.over.samples, rows: s.over.rows } : undefined;
    return { base: { target: base, samples: s.samples, drawn: s.size }, over };
  }
}
