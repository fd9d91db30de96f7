/**
 * The pictures a program samples (image colouring, image seeds) as textures, cached by src.
 * Each is SRGB8_ALPHA8 (the GPU decodes texels to linear light before filtering, as the CPU's
 * shader-gen/picture.ts samplePicture does), LINEAR filtering without mipmaps, REPEAT wrap, row 0
 * = the picture's top row (v = 0). The built-in picture is drawn on the CPU and uploaded at once;
 * a data: URL is decoded with createImageBitmap, and until it is ready a 1×1 grey stands in
 * (`onReady` then restarts the picture). A live picture key (nodes/core/live-source.ts) binds the
 * live texture once it has a frame (live-textures.ts), else its fallback picture.
 */
import { parseLiveKey } from '../../nodes/core/live-source.ts';
import { BUILTIN_PICTURE } from '../../nodes/core/values.ts';
import { PICTURE_SAMPLER } from '../../shader-gen/glsl/values.ts';
import { builtinPicture } from '../../shader-gen/picture.ts';
import { LiveTextures } from './live-textures.ts';
import type { GpuProgram } from './uniforms.ts';

type Entry =
  | { state: 'loading'; promise: Promise<void> }
  | { state: 'ready'; texture: WebGLTexture }
  | { state: 'failed'; reason: string };

/** Decoded pictures kept per context (least recently used go first). */
const MAX_CACHED = 16;

export class PictureTextures {
  private readonly entries = new Map<string, Entry>();
  private placeholder: WebGLTexture | null = null;
  /** The camera's and videos' frames (the viewport refills them every animation frame). */
  readonly live: LiveTextures;

  constructor(
    private readonly gl: WebGL2RenderingContext,
    private readonly onReady: () => void = () => {},
  ) {
    this.live = new LiveTextures(gl);
  }

  /**
   * Binds pictures[i] to texture unit i and points sampler u_image{i} at it; the program must be
   * in use. Returns false while a picture is still loading (a placeholder is bound for it).
   */
  bind(gp: GpuProgram, pictures: readonly string[]): boolean {
    const gl = this.gl;
    let ready = true;
    pictures.forEach((key, i) => {
      const live = this.live.texture(key);
      const entry = live ? null : this.obtain(parseLiveKey(key)?.fallback ?? key);
      ready &&= entry?.state !== 'loading';
      gl.activeTexture(gl.TEXTURE0 + i);
      gl.bindTexture(gl.TEXTURE_2D, live ?? (entry?.state === 'ready' ? entry.texture : this.grey()));
      const name = `${PICTURE_SAMPLER}${i}`;
      let loc = gp.locations.get(name);
      if (loc === undefined) {
        loc = gl.getUniformLocation(gp.program, name);
        (gp.locations as Map<string, WebGLUniformLocation | null>).set(name, loc);
      }
      if (loc !== null) gl.uniform1i(loc, i);
    });
    gl.activeTexture(gl.TEXTURE0);
    return ready;
  }

  /** Resolves once every picture is decoded (or has failed: then the placeholder shows). */
  async whenReady(pictures: readonly string[]): Promise<void> {
    for (const key of pictures) {
      const entry = this.obtain(parseLiveKey(key)?.fallback ?? key);
      if (entry.state === 'loading') await entry.promise;
    }
  }

  /** Why a picture could not be shown, or null. */
  problem(src: string): string | null {
    const entry = this.entries.get(src);
    return entry?.state === 'failed' ? entry.reason : null;
  }

  dispose(): void {
    this.live.dispose();
    if (this.gl.isContextLost()) return;
    for (const entry of this.entries.values())
      if (entry.state === 'ready') this.gl.deleteTexture(entry.texture);
    if (this.placeholder) this.gl.deleteTexture(this.placeholder);
    this.entries.clear();
  }

  private obtain(src: string): Entry {
    const found = this.entries.get(src);
    if (found) {
      // Most recently used last.
      this.entries.delete(src);
      this.entries.set(src, found);
      return found;
    }
    let entry: Entry;
    if (src === BUILTIN_PICTURE.src) {
      const pic = builtinPicture();
      entry = { state: 'ready', texture: this.upload(pic.width, pic.height, pic.data) };
    } else {
      const promise = decode(src).then(
        (bitmap) => {
          this.entries.set(src, {
            state: 'ready',
            texture: this.upload(bitmap.width, bitmap.height, bitmap),
          });
          bitmap.close();
          this.onReady();
        },
        (e: unknown) => {
          const reason = e instanceof Error ? e.message : String(e);
          console.warn(`[kleinflow] picture could not be decoded: ${reason}`);
          this.entries.set(src, { state: 'failed', reason });
          this.onReady();
        },
      );
      entry = { state: 'loading', promise };
    }
    this.entries.set(src, entry);
    this.evict();
    return entry;
  }

  private evict(): void {
    while (this.entries.size > MAX_CACHED) {
      const [oldest, entry] = this.entries.entries().next().value as [string, Entry];
      if (entry.state === 'loading') break;
      if (entry.state === 'ready' && !this.gl.isContextLost()) this.gl.deleteTexture(entry.texture);
      this.entries.delete(oldest);
    }
  }

  private upload(width: number, height: number, pixels: ArrayBufferView | ImageBitmap): WebGLTexture {
    const gl = this.gl;
    const texture = gl.createTexture();
    if (!texture) throw new Error('could not create a texture');
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
    gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, false);
    gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
    if (pixels instanceof ImageBitmap)
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.SRGB8_ALPHA8, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    else {
      const bytes = new Uint8Array(pixels.buffer, pixels.byteOffset, pixels.byteLength);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.SRGB8_ALPHA8, width, height, 0, gl.RGBA, gl.UNSIGNED_BYTE, bytes);
    }
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
    gl.bindTexture(gl.TEXTURE_2D, null);
    return texture;
  }

  private grey(): WebGLTexture {
    this.placeholder ??= this.upload(1, 1, new Uint8Array([128, 128, 128, 255]));
    return this.placeholder;
  }
}

/** A data: URL (or any URL the page may fetch) → an ImageBitmap, not colour-converted. */
async function decode(src: string): Promise<ImageBitmap> {
  const response = await fetch(src);
  if (!response.ok) throw new Error(`could not read the picture (${response.status})`);
  const blob = await response.blob();
  return createImageBitmap(blob, { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
}
