/**
 * Offscreen render targets: a float accumulation buffer of the jittered samples (linear light)
 * and an 8-bit sRGB buffer (SRGB8_ALPHA8: it encodes linear light on write) to read a resolved
 * picture back.
 */

/**
 * How samples are folded into an accumulation target. `sum`: Σ(rgb·a, a), exact for any alpha
 * (transparent export), needs blendable 32-bit floats. `mean`: the running mean of (rgb, a), which
 * stays in [0, 1] and so is precise in half floats; straight rgb, so partly transparent pixels
 * carry some background colour (only a transparent export without EXT_float_blend sees that).
 */
export type AccumulationMode = 'sum' | 'mean';

export interface RenderTarget {
  readonly texture: WebGLTexture;
  readonly framebuffer: WebGLFramebuffer;
  readonly width: number;
  readonly height: number;
  readonly mode: AccumulationMode;
}

/** accumulation: see accumulationFormat; srgb8: 8-bit sRGB readback; probe: exact RGBA32F (needs EXT_color_buffer_float). */
export type TargetKind = 'accumulation' | 'srgb8' | 'probe';

/**
 * The accumulation format: RGBA32F when float targets can be blended (EXT_float_blend), else
 * RGBA16F (blendable wherever EXT_color_buffer_float is); without float targets, RGBA8.
 */
function accumulationFormat(gl: WebGL2RenderingContext): {
  internal: number;
  type: number;
  mode: AccumulationMode;
} {
  if (gl.getExtension('EXT_color_buffer_float')) {
    if (gl.getExtension('EXT_float_blend')) return { internal: gl.RGBA32F, type: gl.FLOAT, mode: 'sum' };
    return { internal: gl.RGBA16F, type: gl.HALF_FLOAT, mode: 'mean' };
  }
  return { internal: gl.RGBA8, type: gl.UNSIGNED_BYTE, mode: 'mean' };
}

export function createTarget(
  gl: WebGL2RenderingContext,
  width: number,
  height: number,
  kind: TargetKind,
): RenderTarget {
  const texture = gl.createTexture();
  const framebuffer = gl.createFramebuffer();
  if (!texture || !framebuffer) throw new Error('WebGL could not create a render target (context lost?)');
  const { internal, type, mode } =
    kind === 'accumulation'
      ? accumulationFormat(gl)
      : kind === 'probe'
        ? { internal: gl.RGBA32F, type: gl.FLOAT, mode: 'mean' as const }
        : { internal: gl.SRGB8_ALPHA8, type: gl.UNSIGNED_BYTE, mode: 'mean' as const };
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texImage2D(gl.TEXTURE_2D, 0, internal, width, height, 0, gl.RGBA, type, null);
  // texelFetch only: no filtering, no mipmaps.
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  gl.bindTexture(gl.TEXTURE_2D, null);
  if (status !== gl.FRAMEBUFFER_COMPLETE && !gl.isContextLost()) {
    gl.deleteFramebuffer(framebuffer);
    gl.deleteTexture(texture);
    throw new Error(`render target ${width}×${height} (${kind}) is incomplete: 0x${status.toString(16)}`);
  }
  return { texture, framebuffer, width, height, mode };
}

export function disposeTarget(gl: WebGL2RenderingContext, t: RenderTarget | null): void {
  if (!t || gl.isContextLost()) return;
  gl.deleteFramebuffer(t.framebuffer);
  gl.deleteTexture(t.texture);
}

/** Reads a width×height 8-bit RGBA region of the bound read framebuffer, flipped to top-row-first. */
export function readTopRowFirst(
  gl: WebGL2RenderingContext,
  width: number,
  height: number,
): Uint8ClampedArray {
  const raw = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, raw);
  const out = new Uint8ClampedArray(raw.length);
  const row = width * 4;
  for (let y = 0; y < height; y++) out.set(raw.subarray(y * row, (y + 1) * row), (height - 1 - y) * row);
  return out;
}
