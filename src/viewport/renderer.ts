/**
 * Every GL object of one context: the program cache, the resolve pass, an empty vertex array.
 * The whole thing is dropped on context loss and rebuilt on restore. Draw calls set all the state
 * they rely on, so the interactive loop and an export can interleave their draws.
 */
import type { UniformEntry } from '../../shader-gen/glsl/values.ts';
import { bindProgram } from './gl-program.ts';
import { PictureTextures } from './picture-textures.ts';
import { ProgramCache } from './program-cache.ts';
import { createTarget, type RenderTarget, readTopRowFirst } from './render-target.ts';
import { type Extent, ResolvePass } from './resolve-pass.ts';
import { canvasEncodesSrgb } from './srgb-canvas.ts';
import { type FrameParams, type GpuProgram, setFrameUniforms, uploadUniforms } from './uniforms.ts';

/**
 * An accumulation target to resolve: `samples` accumulated; `drawn`, the part of it drawn when
 * smaller than the destination (stretched over it); `rows`, GL rows [y0, y1) to resolve alone.
 */
export interface Layer {
  readonly target: RenderTarget;
  readonly samples: number;
  readonly drawn?: Extent;
  readonly rows?: readonly [number, number];
}

export class Renderer {
  readonly programs: ProgramCache;
  /** The pictures programs sample, as textures (cached by src). */
  readonly pictures: PictureTextures;
  private readonly resolvePass: ResolvePass;
  private readonly vao: WebGLVertexArrayObject | null;

  /** `onPictureReady`: a picture finished decoding (the picture should be drawn again). */
  constructor(
    readonly gl: WebGL2RenderingContext,
    onPictureReady?: () => void,
  ) {
    this.programs = new ProgramCache(gl);
    this.pictures = new PictureTextures(gl, onPictureReady);
    this.resolvePass = new ResolvePass(gl);
    this.vao = gl.createVertexArray();
    // Enable the extensions once (getExtension enables them for the context).
    gl.getExtension('EXT_color_buffer_float');
    gl.getExtension('EXT_float_blend');
    gl.getExtension('KHR_parallel_shader_compile');
  }

  /** The largest square tile this context can render into. */
  maxTile(): number {
    const gl = this.gl;
    return Math.min(gl.getParameter(gl.MAX_RENDERBUFFER_SIZE), gl.getParameter(gl.MAX_TEXTURE_SIZE));
  }

  /**
   * Draws sample number `k` (0-based) of `frame` into `target`'s first width×height pixels and
   * folds it in (render-target.ts AccumulationMode): `sum` adds (rgb·a, a) to a buffer cleared at
   * k = 0; `mean` blends dst ← dst + (src − dst)/(k+1) (constant weight 1/(k+1); k = 0 replaces).
   * `pictures` (CompiledProgram.pictures) are bound to texture units 0, 1, ….
   */
  drawSample(
    gp: GpuProgram,
    uniforms: readonly UniformEntry[],
    target: RenderTarget,
    width: number,
    height: number,
    frame: FrameParams,
    k: number,
    pictures: readonly string[] = [],
  ): void {
    const gl = this.gl;
    this.prepareDraw(gp, uniforms, target, width, height, frame, pictures);
    gl.enable(gl.BLEND);
    gl.blendEquation(gl.FUNC_ADD);
    if (target.mode === 'sum') {
      if (k === 0) {
        gl.clearColor(0, 0, 0, 0);
        gl.clear(gl.COLOR_BUFFER_BIT);
      }
      gl.blendFuncSeparate(gl.SRC_ALPHA, gl.ONE, gl.ONE, gl.ONE);
    } else {
      gl.blendColor(0, 0, 0, 1 / (k + 1));
      gl.blendFunc(gl.CONSTANT_ALPHA, gl.ONE_MINUS_CONSTANT_ALPHA);
    }
    this.drawTriangle();
    gl.disable(gl.BLEND);
  }

  /**
   * Draws `frame` into `target`'s first width×height pixels as the program writes it, with no
   * blending: a probe's exact floats (pixel-probe.ts).
   */
  drawExact(
    gp: GpuProgram,
    uniforms: readonly UniformEntry[],
    target: RenderTarget,
    width: number,
    height: number,
    frame: FrameParams,
    pictures: readonly string[] = [],
  ): void {
    this.prepareDraw(gp, uniforms, target, width, height, frame, pictures);
    this.gl.disable(this.gl.BLEND);
    this.drawTriangle();
  }

  /** Binds the target, the program, its uniforms, the frame's uniforms and the pictures. */
  private prepareDraw(
    gp: GpuProgram,
    uniforms: readonly UniformEntry[],
    target: RenderTarget,
    width: number,
    height: number,
    frame: FrameParams,
    pictures: readonly string[],
  ): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
    gl.viewport(0, 0, width, height);
    bindProgram(gl, gp.program);
    if (gp.uploaded !== uniforms) uploadUniforms(gl, gp, uniforms);
    setFrameUniforms(gl, gp, frame);
    if (pictures.length > 0) this.pictures.bind(gp, pictures);
  }

  private drawTriangle(): void {
    const gl = this.gl;
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
  }

  /**
   * Resolves `base` to sRGB on the canvas (its drawing buffer is width×height; sRGB encoded by the
   * buffer itself where srgb-canvas.ts got an sRGB one), then `over`'s rows on top.
   */
  present(base: Layer, width: number, height: number, over?: Layer): void {
    this.resolve(null, canvasEncodesSrgb(this.gl), width, height, base, over);
  }

  /** Resolves width×height of `base` (and `over`'s rows) into `scratch` (SRGB8_ALPHA8) and reads it back, top row first. */
  readResolved(
    base: Layer,
    scratch: RenderTarget,
    width: number,
    height: number,
    over?: Layer,
  ): Uint8ClampedArray {
    const gl = this.gl;
    this.resolve(scratch.framebuffer, true, width, height, base, over);
    gl.bindFramebuffer(gl.FRAMEBUFFER, scratch.framebuffer);
    const pixels = readTopRowFirst(gl, width, height);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return pixels;
  }

  private resolve(
    framebuffer: WebGLFramebuffer | null,
    srgb: boolean,
    width: number,
    height: number,
    base: Layer,
    over?: Layer,
  ): void {
    const gl = this.gl;
    const pass = (l: Layer) =>
      this.resolvePass.draw(
        l.target.texture,
        this.resolveCount(l),
        framebuffer,
        width,
        height,
        srgb,
        l.drawn,
      );
    pass(base);
    if (!over) return;
    const [y0, y1] = over.rows ?? [0, height];
    gl.enable(gl.SCISSOR_TEST);
    gl.scissor(0, y0, width, y1 - y0);
    pass(over);
    gl.disable(gl.SCISSOR_TEST);
  }

  private resolveCount(l: Layer): number {
    return l.target.mode === 'sum' ? l.samples : 1;
  }

  /** A float accumulation target and its 8-bit sRGB readback twin. */
  createTargets(width: number, height: number): { accum: RenderTarget; readback: RenderTarget } {
    return {
      accum: createTarget(this.gl, width, height, 'accumulation'),
      readback: createTarget(this.gl, width, height, 'srgb8'),
    };
  }

  dispose(): void {
    this.programs.dispose();
    this.pictures.dispose();
    this.resolvePass.dispose();
    if (!this.gl.isContextLost()) this.gl.deleteVertexArray(this.vao);
  }
}
