/**
 * The browser side of the viewport tests, bundled by tests/support/bundle.ts and loaded into a
 * blank page with a <canvas>. The Node side drives it through `window.kfViewport`; images travel
 * back as base64 RGBA, top row first.
 */
import type { Diagnostic } from '../../../../nodes/core/diagnostics.ts';
import type { Scene, View } from '../../../../nodes/core/scene.ts';
import type { Scene3d } from '../../../../nodes/core/scene-3d.ts';
import { Renderer } from '../../../../src/viewport/renderer.ts';
import { attachPanZoom, type RenderToPixelsOptions, Viewport } from '../../../../src/viewport/viewport.ts';

function toBase64(a: Uint8ClampedArray | null): string | null {
  if (!a) return null;
  let s = '';
  for (let i = 0; i < a.length; i += 0x8000) s += String.fromCharCode(...a.subarray(i, i + 0x8000));
  return btoa(s);
}

const nextFrame = () => new Promise<number>((r) => requestAnimationFrame(r));

/** Makes every shader whose text has `#line 1 N` fail to compile inside that block (source string N). */
let injectInto: number | null = null;
const originalShaderSource = WebGL2RenderingContext.prototype.shaderSource;
WebGL2RenderingContext.prototype.shaderSource = function (shader: WebGLShader, source: string) {
  const marker = `#line 1 ${injectInto}\n`;
  const patched =
    injectInto !== null && source.includes(marker)
      ? source.replace(marker, `${marker}kf_injected_error = 1.0;\n`)
      : source;
  originalShaderSource.call(this, shader, patched);
};

/**
 * Driver differences to test on SwiftShader: `noFloatBlend` hides EXT_float_blend (the half-float
 * running-mean path); `parallelCompile` fakes KHR_parallel_shader_compile, reporting each program
 * as still compiling for its first two status queries.
 */
const quirks = { noFloatBlend: false, parallelCompile: false };
export type Quirks = typeof quirks;
const COMPLETION_STATUS_KHR = 0x91b1;
let completionQueries = 0;
const statusAsked = new WeakMap<WebGLProgram, number>();
const originalGetExtension = WebGL2RenderingContext.prototype.getExtension;
WebGL2RenderingContext.prototype.getExtension = function (this: WebGL2RenderingContext, name: string) {
  if (quirks.noFloatBlend && name === 'EXT_float_blend') return null;
  if (quirks.parallelCompile && name === 'KHR_parallel_shader_compile') {
    return { COMPLETION_STATUS_KHR, maxShaderCompilerThreadsKHR() {} };
  }
  return originalGetExtension.call(this, name);
} as typeof WebGL2RenderingContext.prototype.getExtension;
const originalProgramParameter = WebGL2RenderingContext.prototype.getProgramParameter;
WebGL2RenderingContext.prototype.getProgramParameter = function (p: WebGLProgram, pname: number) {
  if (pname !== COMPLETION_STATUS_KHR) return originalProgramParameter.call(this, p, pname);
  completionQueries++;
  const asked = (statusAsked.get(p) ?? 0) + 1;
  statusAsked.set(p, asked);
  return asked > 2;
};

const canvas = document.querySelector('canvas') as HTMLCanvasElement;
let capture: ((frame: { shown: string; snapshot: string }) => void) | null = null;

/** The canvas's pixels as the page sees them, top row first. */
function canvasPixels(): Uint8ClampedArray {
  const copy = document.createElement('canvas');
  copy.width = canvas.width;
  copy.height = canvas.height;
  const ctx = copy.getContext('2d') as CanvasRenderingContext2D;
  ctx.drawImage(canvas, 0, 0);
  return ctx.getImageData(0, 0, copy.width, copy.height).data;
}
let vp: Viewport | null = null;
let view: View = { center: [0, 0], scale: 1 };
const diagnostics: Diagnostic[][] = [];
/** Every frame drawn: its onFrame info and whether the baked program drew it. */
const frameLog: { samples: number; target: number; ms: number; baked: boolean }[] = [];
/** base64 snapshots taken after every frame while recording. */
let recorded: string[] = [];
let recording = false;

const harness = {
  diagnostics,
  frameLog,
  completionQueries: () => completionQueries,
  create(
    width: number,
    height: number,
    idleBakeMs = 600,
    withQuirks: Partial<Quirks> = {},
    bandMs: number | undefined = undefined,
  ): void {
    vp?.dispose();
    Object.assign(quirks, { noFloatBlend: false, parallelCompile: false }, withQuirks);
    diagnostics.length = 0;
    frameLog.length = 0;
    vp = new Viewport(canvas, {
      idleBakeMs,
      bandMs,
      onDiagnostics: (d) => diagnostics.push(d),
      onFrame: (info) => {
        frameLog.push({ ...info, baked: vp!.stats.baked });
        if (recording) recorded.push(toBase64(vp!.snapshot())!);
        if (capture) {
          // Right after the frame is presented: the drawing buffer still holds it.
          capture({ shown: toBase64(canvasPixels())!, snapshot: toBase64(vp!.snapshot())! });
          capture = null;
        }
      },
    });
    vp.setSize(width, height, 1);
  },
  setScene(scene: Scene | Scene3d): void {
    if ('view' in scene) view = scene.view;
    vp!.setScene(scene);
  },
  setView(v: View): void {
    view = v;
    vp!.setView(v);
  },
  view: () => view,
  stats: () => vp!.stats,
  snapshot: () => toBase64(vp!.snapshot()),
  /**
   * The next frame as the canvas shows it (drawn into a 2D canvas, so the browser interprets the
   * drawing buffer's format) and as snapshot() resolves it, both taken right after it is presented.
   */
  nextFrameShown(): Promise<{ shown: string; snapshot: string }> {
    return new Promise((resolve) => {
      capture = resolve;
    });
  },
  /**
   * Linear values `linear` (one opaque pixel each, as one accumulated sample) resolved by the
   * renderer into its 8-bit sRGB readback target: the bytes of each pixel's red channel.
   */
  resolveLinear(linear: number[]): number[] {
    const gl = document.createElement('canvas').getContext('webgl2') as WebGL2RenderingContext;
    const r = new Renderer(gl);
    const { accum, readback } = r.createTargets(linear.length, 1);
    if (accum.mode !== 'sum') throw new Error('this check needs a float accumulation target');
    const data = new Float32Array(linear.flatMap((v) => [v, v, v, 1]));
    gl.bindTexture(gl.TEXTURE_2D, accum.texture);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, linear.length, 1, gl.RGBA, gl.FLOAT, data);
    gl.bindTexture(gl.TEXTURE_2D, null);
    const px = r.readResolved({ target: accum, samples: 1 }, readback, linear.length, 1);
    r.dispose();
    return linear.map((_, i) => px[i * 4]);
  },
  /** Whether the canvas's drawing buffer is SRGB8_ALPHA8 (src/viewport/srgb-canvas.ts). */
  canvasIsSrgb(): boolean {
    const gl = canvas.getContext('webgl2') as WebGL2RenderingContext & { drawingBufferFormat?: number };
    return gl.drawingBufferFormat === gl.SRGB8_ALPHA8;
  },
  record(on: boolean): string[] {
    recording = on;
    const out = recorded;
    if (on) recorded = [];
    return out;
  },
  /** Resolves once `samples` samples are on screen (or rejects after timeoutMs). */
  async waitSamples(samples: number, timeoutMs = 20_000): Promise<void> {
    const end = performance.now() + timeoutMs;
    while (vp!.stats.samples < samples || vp!.stats.frames === 0) {
      if (performance.now() > end) throw new Error(`timed out at ${JSON.stringify(vp!.stats)}`);
      await nextFrame();
    }
  },
  /** Resolves once `frames` frames have been drawn in all. */
  async waitFrames(frames: number, timeoutMs = 20_000): Promise<void> {
    const end = performance.now() + timeoutMs;
    while (vp!.stats.frames < frames) {
      if (performance.now() > end) throw new Error(`timed out at ${JSON.stringify(vp!.stats)}`);
      await nextFrame();
    }
  },
  /** Resolves once no frame has been drawn for `quietMs`. */
  async waitStill(quietMs = 300): Promise<void> {
    let frames = vp!.stats.frames;
    let since = performance.now();
    while (performance.now() - since < quietMs) {
      await nextFrame();
      if (vp!.stats.frames !== frames) {
        frames = vp!.stats.frames;
        since = performance.now();
      }
    }
  },
  async waitBaked(timeoutMs = 20_000): Promise<void> {
    const end = performance.now() + timeoutMs;
    while (!vp!.stats.baked) {
      if (performance.now() > end) throw new Error('the baked program never took over');
      await nextFrame();
    }
  },
  injectError(sourceNumber: number | null): void {
    injectInto = sourceNumber;
  },
  async loseAndRestoreContext(): Promise<void> {
    const gl = canvas.getContext('webgl2')!;
    const ext = gl.getExtension('WEBGL_lose_context')!;
    const lost = new Promise((r) => canvas.addEventListener('webglcontextlost', r, { once: true }));
    ext.loseContext();
    await lost;
    await nextFrame();
    const restored = new Promise((r) => canvas.addEventListener('webglcontextrestored', r, { once: true }));
    ext.restoreContext();
    await restored;
  },
  async renderToPixels(opts: Omit<RenderToPixelsOptions, 'onProgress'>, cancelAt?: number) {
    const progress: number[] = [];
    const pixels = await vp!.renderToPixels({
      ...opts,
      onProgress: (f) => {
        progress.push(f);
        return cancelAt === undefined || f < cancelAt;
      },
    });
    return { pixels: toBase64(pixels), progress };
  },
  detachPanZoom: null as (() => void) | null,
  attachPanZoom(): void {
    const host = canvas.parentElement as HTMLElement;
    harness.detachPanZoom = attachPanZoom(
      host,
      () => view,
      (v) => harness.setView(v),
    );
  },
  /** The overlay's way of claiming a drag: preventDefault on pointerdown before it bubbles up. */
  claimPointerDowns(on: boolean): void {
    canvas.onpointerdown = on ? (e) => e.preventDefault() : null;
  },
  /** Dispatches a synthetic touch pointer event on the canvas (two-finger gestures). */
  touch(type: 'pointerdown' | 'pointermove' | 'pointerup', pointerId: number, x: number, y: number): void {
    const r = canvas.getBoundingClientRect();
    const init = {
      pointerId,
      pointerType: 'touch',
      clientX: r.left + x,
      clientY: r.top + y,
      bubbles: true,
      cancelable: true,
    };
    canvas.dispatchEvent(new PointerEvent(type, init));
  },
};

declare global {
  interface Window {
    kfViewport: typeof harness;
  }
}
window.kfViewport = harness;
