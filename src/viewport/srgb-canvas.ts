/**
 * An sRGB drawing buffer for the canvas (WebGL 2's drawingBufferStorage with SRGB8_ALPHA8): the
 * resolve pass then writes linear light and the framebuffer encodes it to sRGB on write, in fixed
 * function, instead of the shader evaluating the transfer function per pixel (shader-gen/srgb.ts;
 * `pow` is slow in software rendering). Browsers without it keep the default RGBA8 buffer and the
 * shader encodes (resolve-pass.ts).
 */

const CONTEXT_ATTRIBUTES: WebGLContextAttributes = {
  // An RGBA drawing buffer: only such a buffer can become SRGB8_ALPHA8. The picture stays opaque:
  // on screen u_bgAlpha is 1, so every resolved pixel has alpha 1.
  alpha: true,
  antialias: false,
  depth: false,
  stencil: false,
  preserveDrawingBuffer: false,
  powerPreference: 'high-performance',
};

/** The live picture's WebGL2 context, its drawing buffer sRGB where the browser can. */
export function openSrgbCanvas(canvas: HTMLCanvasElement): WebGL2RenderingContext {
  const gl = canvas.getContext('webgl2', CONTEXT_ATTRIBUTES);
  if (!gl) throw new Error('WebGL2 is not available in this browser');
  requestSrgbDrawingBuffer(gl, canvas.width, canvas.height);
  return gl;
}

/** Sizes the canvas to width × height CSS px of `dpr` device pixels each, asking again for an sRGB buffer. */
export function sizeSrgbCanvas(
  gl: WebGL2RenderingContext,
  canvas: HTMLCanvasElement,
  width: number,
  height: number,
  dpr: number,
): void {
  const w = Math.max(1, Math.round(width * dpr));
  const h = Math.max(1, Math.round(height * dpr));
  if (canvas.width !== w) canvas.width = w;
  if (canvas.height !== h) canvas.height = h;
  requestSrgbDrawingBuffer(gl, w, h);
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
}

/** The parts of WebGL2RenderingContext that TypeScript's DOM types do not have yet. */
interface SrgbDrawingBufferApi {
  drawingBufferStorage?: (format: number, width: number, height: number) => void;
  readonly drawingBufferFormat?: number;
}

/**
 * Asks for a width×height SRGB8_ALPHA8 drawing buffer (call after every canvas resize: a resize
 * may bring the default format back). Returns whether the canvas now encodes sRGB itself.
 */
export function requestSrgbDrawingBuffer(gl: WebGL2RenderingContext, width: number, height: number): boolean {
  const api = gl as WebGL2RenderingContext & SrgbDrawingBufferApi;
  const max = gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number;
  if (typeof api.drawingBufferStorage === 'function' && width <= max && height <= max) {
    api.drawingBufferStorage(gl.SRGB8_ALPHA8, width, height);
  }
  return canvasEncodesSrgb(gl);
}

/** Whether the canvas's drawing buffer is SRGB8_ALPHA8 (then draw linear light into it). */
export function canvasEncodesSrgb(gl: WebGL2RenderingContext): boolean {
  return (gl as WebGL2RenderingContext & SrgbDrawingBufferApi).drawingBufferFormat === gl.SRGB8_ALPHA8;
}
