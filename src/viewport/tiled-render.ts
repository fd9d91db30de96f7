/**
 * Offscreen, tiled, full-quality render (PNG export): the image is cut into tiles no larger than
 * the context allows; each tile accumulates every sample (the same jitter sequence as the canvas)
 * and is resolved to 8-bit sRGB and read back. Between samples control returns to the page, so the
 * editor stays responsive; onProgress can cancel.
 */
import type { View } from '../../nodes/core/scene.ts';
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import type { UniformEntry } from '../../shader-gen/glsl/values.ts';
import { sampleOffset } from '../../shader-gen/view.ts';
import { disposeTarget } from './render-target.ts';
import type { Renderer } from './renderer.ts';
import type { GpuProgram } from './uniforms.ts';

export const DEFAULT_TILE = 1024;

export interface TiledRenderOptions {
  readonly width: number;
  readonly height: number;
  readonly samples: number;
  readonly view: View;
  /** A 3D program's camera. */
  readonly camera?: Camera3d;
  readonly transparent: boolean;
  readonly tile?: number;
  /** Fraction done in [0, 1]; return false to cancel. */
  // biome-ignore lint/suspicious/noConfusingVoidType: callbacks that return nothing must fit
  readonly onProgress?: (fraction: number) => boolean | void;
}

/** Lets the browser run a frame (and other tasks) between two chunks of GPU work. */
const yieldToPage = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/**
 * Renders the picture; `program()` is asked before every draw (the caller may switch to a faster
 * program, or throw when the context is lost). Returns RGBA, top row first, or null when cancelled.
 */
export async function renderTiled(
  renderer: () => Renderer,
  program: () => { gp: GpuProgram; uniforms: readonly UniformEntry[]; pictures?: readonly string[] },
  o: TiledRenderOptions,
): Promise<Uint8ClampedArray | null> {
  const { width, height } = o;
  if (!(Number.isInteger(width) && Number.isInteger(height) && width > 0 && height > 0)) {
    throw new Error(`renderToPixels: bad size ${width}×${height}`);
  }
  const samples = Math.max(1, Math.round(o.samples));
  const tile = Math.max(1, Math.min(Math.floor(o.tile ?? DEFAULT_TILE), renderer().maxTile()));
  const tilesX = Math.ceil(width / tile);
  const tilesY = Math.ceil(height / tile);
  const total = tilesX * tilesY * samples;
  const out = new Uint8ClampedArray(width * height * 4);
  const r0 = renderer();
  const targets = r0.createTargets(Math.min(tile, width), Math.min(tile, height));
  let done = 0;
  try {
    // ty counts tiles from the bottom (GL's origin); the output is top row first.
    for (let ty = 0; ty < tilesY; ty++) {
      for (let tx = 0; tx < tilesX; tx++) {
        const x0 = tx * tile;
        const y0 = ty * tile;
        const tw = Math.min(tile, width - x0);
        const th = Math.min(tile, height - y0);
        for (let k = 0; k < samples; k++) {
          const r = renderer();
          if (r !== r0) throw new Error('renderToPixels: the WebGL context was lost');
          const { gp, uniforms, pictures } = program();
          const frame = {
            width,
            height,
            offsetX: x0,
            offsetY: y0,
            view: o.view,
            camera: o.camera,
            jitter: sampleOffset(k),
            bgAlpha: o.transparent ? 0 : 1,
          };
          r.drawSample(gp, uniforms, targets.accum, tw, th, frame, k, pictures);
          done++;
          if (o.onProgress?.(done / total) === false) return null;
          await yieldToPage();
        }
        const pixels = r0.readResolved({ target: targets.accum, samples }, targets.readback, tw, th);
        // Tile row 0 (top of the tile) lands on image row height − (y0 + th).
        const top = height - (y0 + th);
        for (let y = 0; y < th; y++) {
          out.set(pixels.subarray(y * tw * 4, (y + 1) * tw * 4), ((top + y) * width + x0) * 4);
        }
      }
    }
  } finally {
    if (renderer() === r0) {
      disposeTarget(r0.gl, targets.accum);
      disposeTarget(r0.gl, targets.readback);
    }
  }
  return out;
}
