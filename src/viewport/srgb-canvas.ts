/**
 * An sRGB drawing buffer for the canvas (WebGL 2's drawingBufferStorage with SRGB8_ALPHA8): the
 * resolve pass then writes linear light and the framebuffer encodes it to sRGB on write, in fixed
 * function, instead of the shader evaluating the transfer function per pixel (shader-gen/srgb.ts;
 * `pow` is slow in software rendering). Browsers without it keep the default RGBA8 buffer and the
 * shader encodes (resolve-pass.ts).
 */

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
