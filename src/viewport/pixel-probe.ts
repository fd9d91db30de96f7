/**
 * What the GPU decides at one pixel ("Explain this pixel"): the scene's inspect variant
 * (shader-gen compile, INSPECT_STOP) drawn into a 1×1 RGBA32F target as that pixel of the canvas —
 * the same pixel-to-world mapping, at the pixel centre like the picture's first sample — and read
 * back exactly. The editor compares it with the CPU trace and shows any disagreement.
 */
import type { Scene, View } from '../../nodes/core/scene.ts';
import { pixelToWorld } from '../../nodes/core/view.ts';
import { compile, INSPECT_STOP } from '../../shader-gen/compile.ts';
import type { StopReason } from '../../shader-gen/trace.ts';
import { createTarget, disposeTarget } from './render-target.ts';
import type { Renderer } from './renderer.ts';

export interface GpuPixel {
  readonly depth: number;
  readonly final: readonly [number, number];
  readonly stop: StopReason;
  /** The seed the run stopped in (stop 'seed'), else −1. */
  readonly seed: number;
}

/** The GPU's answer, or why there is none (said in the panel, never hidden). */
export type GpuPixelResult =
  | { readonly ok: true; readonly pixel: GpuPixel }
  | { readonly ok: false; readonly reason: string };

/** A pixel of the canvas's drawing buffer, origin bottom-left, and the buffer's size. */
export interface CanvasPixel {
  readonly px: number;
  readonly py: number;
  readonly width: number;
  readonly height: number;
}

/** Viewport.inspectAt's answer: the pixel, the world point at its centre, the GPU's decision there. */
export interface PixelInspection {
  readonly pixel: CanvasPixel;
  readonly world: readonly [number, number];
  readonly gpu: GpuPixelResult;
}

function decodeStop(w: number): { stop: StopReason; seed: number } {
  if (w >= INSPECT_STOP.seed) return { stop: 'seed', seed: Math.round(w - INSPECT_STOP.seed) };
  if (w === INSPECT_STOP.clipped) return { stop: 'clipped', seed: -1 };
  return { stop: w === INSPECT_STOP.tile ? 'fundamental-domain' : 'limit', seed: -1 };
}

export function probePixel(renderer: Renderer, scene: Scene, view: View, at: CanvasPixel): GpuPixelResult {
  const gl = renderer.gl;
  if (gl.isContextLost()) return { ok: false, reason: 'the WebGL context is lost' };
  if (!gl.getExtension('EXT_color_buffer_float')) {
    return { ok: false, reason: 'this GPU cannot render to float targets (EXT_color_buffer_float)' };
  }
  let compiled: ReturnType<typeof compile>;
  try {
    compiled = compile(scene, { variant: 'inspect' });
  } catch (e) {
    return { ok: false, reason: `the shader generator failed: ${(e as Error).message}` };
  }
  const built = renderer.programs.obtain(compiled, { variant: 'inspect' });
  if (!built.ok)
    return { ok: false, reason: `the probe shader did not compile: ${built.error[0]?.message ?? ''}` };
  const target = createTarget(gl, 1, 1, 'probe');
  try {
    const frame = {
      width: at.width,
      height: at.height,
      offsetX: at.px,
      offsetY: at.py,
      view,
      jitter: [0.5, 0.5] as const,
      bgAlpha: 1,
    };
    renderer.drawExact(built.value, compiled.uniforms, target, 1, 1, frame, compiled.pictures);
    const out = new Float32Array(4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, out);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    if (gl.isContextLost()) return { ok: false, reason: 'the WebGL context was lost while reading' };
    return { ok: true, pixel: { depth: out[0], final: [out[1], out[2]], ...decodeStop(out[3]) } };
  } finally {
    disposeTarget(gl, target);
  }
}

/**
 * "Explain this pixel" at a CSS point of `canvas`: the drawing-buffer pixel under it, the world
 * point at its centre (what the picture's first sample shows) and the GPU's depth there.
 */
export function inspectCssPoint(
  renderer: Renderer | null,
  canvas: HTMLCanvasElement,
  scene: Scene,
  view: View,
  css: { readonly x: number; readonly y: number },
): PixelInspection {
  const width = canvas.width;
  const height = canvas.height;
  const clamp = (v: number, n: number) => Math.min(n - 1, Math.max(0, Math.floor(v)));
  const px = clamp((css.x * width) / Math.max(1, canvas.clientWidth), width);
  const py = clamp(height - (css.y * height) / Math.max(1, canvas.clientHeight), height);
  const at = { px, py, width, height };
  const gpu: GpuPixelResult = renderer
    ? probePixel(renderer, scene, view, at)
    : { ok: false, reason: 'the WebGL context is lost' };
  return { pixel: at, world: pixelToWorld(view, width, height, px, py), gpu };
}
