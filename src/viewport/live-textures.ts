/**
 * Textures of live pictures (camera, video), one per live picture key (nodes/core/live-source.ts),
 * refilled from the <video> element whenever it has presented a new frame. The frame is cropped to
 * the key's aspect (the centred largest rectangle of that width:height) with the WebGL2 unpack
 * skip/row-length parameters, so the picture keeps the place and shape of its fallback and the
 * shader never changes. Same texture set-up as picture-textures.ts: SRGB8_ALPHA8, LINEAR, REPEAT.
 */
import { parseLiveKey } from '../../nodes/core/live-source.ts';
import type { LiveFrame } from './live-media.ts';

/** Live textures kept per context (least recently created go first: a source no longer drawn). */
const MAX_LIVE = 8;

interface Entry {
  texture: WebGLTexture;
  width: number;
  height: number;
  /** The frame serial uploaded last (NaN: unknown, upload every time). */
  serial: number;
}

/** The centred crop of a w × h frame to `aspect` (width / height), in whole pixels. */
export function cropToAspect(w: number, h: number, aspect: number) {
  const width = Math.max(1, Math.min(w, Math.round(h * aspect)));
  const height = Math.max(1, Math.min(h, Math.round(w / aspect)));
  return { x: Math.floor((w - width) / 2), y: Math.floor((h - height) / 2), width, height };
}

export class LiveTextures {
  private readonly entries = new Map<string, Entry>();

  constructor(private readonly gl: WebGL2RenderingContext) {}

  /** The texture holding the last frame of `key`, or null before its first frame. */
  texture(key: string): WebGLTexture | null {
    return this.entries.get(key)?.texture ?? null;
  }

  /** Uploads `frame` for `key` unless it is the frame already there; true when the picture changed. */
  update(key: string, frame: LiveFrame): boolean {
    const live = parseLiveKey(key);
    if (!live) return false;
    const found = this.entries.get(key);
    if (found && found.serial === frame.serial) return false;
    const gl = this.gl;
    const { video } = frame;
    const crop = cropToAspect(video.videoWidth, video.videoHeight, live.aspect);
    const entry = found ?? this.create(key);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, entry.texture);
    gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, false);
    gl.pixelStorei(gl.UNPACK_PREMULTIPLY_ALPHA_WEBGL, false);
    gl.pixelStorei(gl.UNPACK_COLORSPACE_CONVERSION_WEBGL, gl.NONE);
    gl.pixelStorei(gl.UNPACK_ROW_LENGTH, video.videoWidth);
    gl.pixelStorei(gl.UNPACK_SKIP_PIXELS, crop.x);
    gl.pixelStorei(gl.UNPACK_SKIP_ROWS, crop.y);
    if (entry.width === crop.width && entry.height === crop.height)
      gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, crop.width, crop.height, gl.RGBA, gl.UNSIGNED_BYTE, video);
    else {
      gl.texImage2D(
        gl.TEXTURE_2D,
        0,
        gl.SRGB8_ALPHA8,
        crop.width,
        crop.height,
        0,
        gl.RGBA,
        gl.UNSIGNED_BYTE,
        video,
      );
      entry.width = crop.width;
      entry.height = crop.height;
    }
    gl.pixelStorei(gl.UNPACK_ROW_LENGTH, 0);
    gl.pixelStorei(gl.UNPACK_SKIP_PIXELS, 0);
    gl.pixelStorei(gl.UNPACK_SKIP_ROWS, 0);
    gl.bindTexture(gl.TEXTURE_2D, null);
    entry.serial = frame.serial;
    return true;
  }

  dispose(): void {
    if (!this.gl.isContextLost()) for (const e of this.entries.values()) this.gl.deleteTexture(e.texture);
    this.entries.clear();
  }

  private create(key: string): Entry {
    const gl = this.gl;
    const texture = gl.createTexture();
    if (!texture) throw new Error('could not create a texture');
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
    const entry = { texture, width: 0, height: 0, serial: Number.NaN };
    this.entries.set(key, entry);
    for (const [old, e] of this.entries) {
      if (this.entries.size <= MAX_LIVE) break;
      gl.deleteTexture(e.texture);
      this.entries.delete(old);
    }
    return entry;
  }
}

/** What one animation frame found: whether any live source runs, and whether a texture changed. */
export interface LiveRefresh {
  readonly running: boolean;
  readonly changed: boolean;
}

/** Refills the live textures among `pictures` (a program's keys) from the sources that run. */
export function refreshLive(
  textures: LiveTextures,
  pictures: readonly string[],
  frameOf: (source: string) => LiveFrame | null,
): LiveRefresh {
  let running = false;
  let changed = false;
  for (const key of pictures) {
    const live = parseLiveKey(key);
    const frame = live && frameOf(live.source);
    if (!frame) continue;
    running = true;
    changed = textures.update(key, frame) || changed;
  }
  return { running, changed };
}
