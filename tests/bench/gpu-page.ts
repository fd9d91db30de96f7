/**
 * The browser side of the GPU benchmark (bundled by tests/support/bundle.ts): compile/link times,
 * frame times at 512² and edit latencies, measured with the runtime's own helpers. Every frame ends
 * with a readPixels, the only reliable wait in Chrome (gl.finish returns at once).
 */
import type { Scene } from '../../nodes/core/scene.ts';
import { type CompileOptions, compile } from '../../shader-gen/compile.ts';
import type { UniformEntry } from '../../shader-gen/glsl/values.ts';
import { linearToSrgb } from '../../shader-gen/srgb.ts';
import { sampleOffset } from '../../shader-gen/view.ts';
import { bindProgram, buildProgram } from '../../src/viewport/gl-program.ts';
import { createTarget } from '../../src/viewport/render-target.ts';
import {
  type GpuProgram,
  locateUniforms,
  setFrameUniforms,
  uploadUniforms,
} from '../../src/viewport/uniforms.ts';
import { FRAME_SIZE, median } from './report.ts';

const SIZE = FRAME_SIZE;

const canvas = document.querySelector('canvas') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2') as WebGL2RenderingContext;
gl.getExtension('EXT_color_buffer_float');
gl.getExtension('EXT_float_blend');
/** RGBA32F: the colour variant's accumulation format and the probe variant's output. */
const target = createTarget(gl, SIZE, SIZE, 'accumulation');
const vao = gl.createVertexArray();
const pixel = new Float32Array(4);
/** Makes every source unique, so Chrome's program cache never answers for the driver. */
let nonce = 0;

interface Built {
  readonly gp: GpuProgram;
  readonly uniforms: readonly UniformEntry[];
  /** Compile + link until the driver reports the link status. */
  readonly linkMs: number;
  /** The first frame after linking (SwiftShader, like some drivers, finishes its JIT there). */
  readonly firstFrameMs: number;
}

function build(
  vertex: string,
  fragment: string,
  uniforms: readonly UniformEntry[],
  view: Scene['view'],
): Built {
  const t0 = performance.now();
  const linked = buildProgram(gl, vertex, `${fragment}\n// bench ${nonce++}\n`);
  if (!linked.ok) throw new Error(linked.error.map((d) => d.message).join('; '));
  const gp = locateUniforms(gl, linked.value, uniforms);
  const linkMs = performance.now() - t0;
  const firstFrameMs = drawFrame({ gp, uniforms }, 0, view);
  return { gp, uniforms, linkMs, firstFrameMs };
}

/** Draws sample k into the 512² target and waits for it (1-pixel readPixels); returns ms. */
function drawFrame(b: Pick<Built, 'gp' | 'uniforms'>, k: number, view: Scene['view']): number {
  const t0 = performance.now();
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  gl.viewport(0, 0, SIZE, SIZE);
  bindProgram(gl, b.gp.program);
  if (b.gp.uploaded !== b.uniforms) uploadUniforms(gl, b.gp, b.uniforms);
  const frame = {
    width: SIZE,
    height: SIZE,
    offsetX: 0,
    offsetY: 0,
    view,
    jitter: sampleOffset(k),
    bgAlpha: 1,
  };
  setFrameUniforms(gl, b.gp, frame);
  gl.bindVertexArray(vao);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, pixel);
  return performance.now() - t0;
}

/** Median frame time over `frames` frames (after one warm-up). */
function frameTime(b: Built, view: Scene['view'], frames: number): number {
  drawFrame(b, 0, view);
  return median(Array.from({ length: frames }, (_, k) => drawFrame(b, k + 1, view)));
}

function buildScene(scene: Scene, options: CompileOptions): Built {
  const c = compile(scene, options);
  return build(c.vertexSource, c.source, c.uniforms, scene.view);
}

export interface GpuBenchResult {
  compileUniformMs: number;
  firstFrameUniformMs: number;
  compileBakedMs: number;
  frameUniformMs: number;
  frameBakedMs: number;
  /** Probe variant (the hand-written shaders' output) when a hand-written shader exists. */
  probe: { uniformMs: number; bakedMs: number; handMs: number } | null;
  structuralEditMs: number;
  valueEditMs: number;
}

function measure(scene: Scene, hand: string | null, frames: number): GpuBenchResult {
  const view = scene.view;
  const uniform = buildScene(scene, { variant: 'color' });
  const baked = buildScene(scene, { variant: 'color', baked: true });
  const frameUniformMs = frameTime(uniform, view, frames);
  const frameBakedMs = frameTime(baked, view, frames);
  let probe: GpuBenchResult['probe'] = null;
  if (hand !== null) {
    const vertex = compile(scene, { variant: 'probe' }).vertexSource;
    probe = {
      uniformMs: frameTime(buildScene(scene, { variant: 'probe' }), view, frames),
      bakedMs: frameTime(buildScene(scene, { variant: 'probe', baked: true }), view, frames),
      handMs: frameTime(build(vertex, hand, [], view), view, frames),
    };
  }
  // Structural edit (an element fewer, or one more): generate, compile, link, first frame.
  const edited: Scene = {
    ...scene,
    elements:
      scene.elements.length > 1 ? scene.elements.slice(0, -1) : [...scene.elements, ...scene.elements],
  };
  let t0 = performance.now();
  buildScene(edited, { variant: 'color' });
  const structuralEditMs = performance.now() - t0;
  // Value edit (what a drag does per frame): generate (the viewport compares uniforms), upload, frame.
  t0 = performance.now();
  const moved = compile(structuredClone(scene), { variant: 'color' });
  const nudged = moved.uniforms.map((u) =>
    u.type === 'int' ? u : { ...u, value: u.value.map((v) => v * (1 + 1e-4)) },
  );
  drawFrame({ gp: uniform.gp, uniforms: nudged }, 0, view);
  const valueEditMs = performance.now() - t0;
  return {
    compileUniformMs: uniform.linkMs,
    firstFrameUniformMs: uniform.firstFrameMs,
    compileBakedMs: baked.linkMs,
    frameUniformMs,
    frameBakedMs,
    probe,
    structuralEditMs,
    valueEditMs,
  };
}

/** Frame times (ms) per program and round of `interleaved`, in the order the programs were given. */
export type InterleavedTimes = Record<string, number[]>;

/**
 * Renders several programs of one scene in turn (A B C A B C …) for `rounds` rounds, all with the
 * round's jitter, after one warm-up frame each: machine-load drift then hits every program alike,
 * so the ratios of their times are trustworthy even where the absolute times are not.
 */
function interleaved(
  scene: Scene,
  programs: Record<string, { vertex: string; fragment: string; uniforms: readonly UniformEntry[] }>,
  rounds: number,
): InterleavedTimes {
  const built = Object.entries(programs).map(
    ([name, p]) => [name, build(p.vertex, p.fragment, p.uniforms, scene.view)] as const,
  );
  const times: InterleavedTimes = {};
  for (const [name, b] of built) {
    drawFrame(b, 0, scene.view);
    times[name] = [];
  }
  for (let r = 0; r < rounds; r++) {
    for (const [name, b] of built) times[name].push(drawFrame(b, r + 1, scene.view));
  }
  return times;
}

/** A program to render, and whether it writes linear light (else sRGB, written as it is). */
export interface OutputProgram {
  readonly vertex: string;
  readonly fragment: string;
  readonly uniforms: readonly UniformEntry[];
  readonly linear: boolean;
}

/** How far two programs' pictures are apart, in 8-bit sRGB levels. */
export interface OutputDifference {
  /** The largest difference of any channel (alpha included) of any pixel. */
  readonly maxLevels: number;
  /** The share of pixels where some channel differs by more than one level (rounding). */
  readonly beyondRounding: number;
}

/** The SIZE² picture of `p` (sample 0, the pixel centres) as 8-bit levels, sRGB-encoded where linear. */
function levels(p: OutputProgram, view: Scene['view']): Uint8Array {
  const b = build(p.vertex, p.fragment, p.uniforms, view);
  drawFrame(b, 0, view);
  const raw = new Float32Array(SIZE * SIZE * 4);
  gl.readPixels(0, 0, SIZE, SIZE, gl.RGBA, gl.FLOAT, raw);
  const clamp = (x: number) => Math.min(1, Math.max(0, x));
  return Uint8Array.from(raw, (x, i) =>
    Math.round((p.linear && i % 4 !== 3 ? linearToSrgb(clamp(x)) : clamp(x)) * 255),
  );
}

/**
 * Equal output, checked: renders each program once and compares the pairs (names of `programs`)
 * pixel by pixel in 8-bit sRGB levels, what a screen or a PNG shows.
 */
function outputDifferences(
  scene: Scene,
  programs: Record<string, OutputProgram>,
  pairs: readonly (readonly [string, string])[],
): OutputDifference[] {
  const images = new Map(Object.entries(programs).map(([name, p]) => [name, levels(p, scene.view)]));
  return pairs.map(([a, b]) => {
    const x = images.get(a) as Uint8Array;
    const y = images.get(b) as Uint8Array;
    let maxLevels = 0;
    let beyond = 0;
    for (let i = 0; i < x.length; i += 4) {
      let worst = 0;
      for (let k = 0; k < 4; k++) worst = Math.max(worst, Math.abs(x[i + k] - y[i + k]));
      maxLevels = Math.max(maxLevels, worst);
      if (worst > 1) beyond++;
    }
    return { maxLevels, beyondRounding: beyond / (SIZE * SIZE) };
  });
}

function renderer(): string {
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  return String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
}

const bench = { measure, renderer, interleaved, outputDifferences };
declare global {
  interface Window {
    kfBench: typeof bench;
  }
}
window.kfBench = bench;
