/**
 * Node side of the parity harness: one Chromium page with webgl-harness.js injected, programs
 * compiled from compile()'s output, probe images read back as Float32Arrays (row 0 at the bottom:
 * pixel (px, py) is at index 4·(py·W + px)).
 */
import { readFileSync } from 'node:fs';
import type { Browser, Page } from 'playwright-core';
import { parseLiveKey } from '../../nodes/core/live-source.ts';
import type { View } from '../../nodes/core/scene.ts';
import type { UniformEntry } from '../../shader-gen/compile.ts';
import { resolvePicture } from '../../shader-gen/picture.ts';
import { launchChromium } from '../support/browser.ts';

const HARNESS = readFileSync(new URL('./webgl-harness.js', import.meta.url), 'utf8');

export interface ProbeImage {
  readonly width: number;
  readonly height: number;
  /** (depth, final.x, final.y, escaped) per pixel, row 0 at the bottom. */
  readonly data: Float32Array;
  /** Milliseconds for the draw and read-back (SwiftShader, noisy). */
  readonly ms: number;
}

export interface FrameOptions {
  /** Size of the whole image (default: the canvas). */
  readonly resolution?: readonly [number, number];
  /** Pixel offset of the canvas within the whole image (default 0, 0). */
  readonly offset?: readonly [number, number];
  readonly bgAlpha?: number;
  /** The program's pictures (CompiledProgram.pictures), bound to its samplers. */
  readonly pictures?: readonly string[];
}

export class GpuProbe {
  private constructor(
    private readonly browser: Browser,
    private readonly page: Page,
    readonly width: number,
    readonly height: number,
    /** The WebGL renderer string (SwiftShader here). */
    readonly renderer: string,
  ) {}

  static async open(width: number, height: number): Promise<GpuProbe> {
    const browser = await launchChromium();
    try {
      const page = await browser.newPage();
      await page.setContent('<!doctype html><html><body></body></html>');
      await page.addScriptTag({ content: HARNESS });
      const renderer = await page.evaluate(([w, h]) => window.kfHarness.init(w, h), [width, height]);
      return new GpuProbe(browser, page, width, height, renderer);
    } catch (e) {
      await browser.close();
      throw e;
    }
  }

  /** Compiles and links; rejects with the compiler's log. Returns the program's index. */
  program(vertexSource: string, fragmentSource: string): Promise<number> {
    return this.page.evaluate(([vs, fs]) => window.kfHarness.program(vs, fs), [vertexSource, fragmentSource]);
  }

  compileCount(): Promise<number> {
    return this.page.evaluate(() => window.kfHarness.compileCount);
  }

  /**
   * Renders with the given view and scene uniforms at the pixel centres (jitter 0.5, 0.5). By
   * default the canvas is the whole image; `tile` renders the canvas as the part at `offset` of an
   * image of `resolution` pixels (tiled export), `bgAlpha` sets u_bgAlpha.
   */
  async render(
    program: number,
    uniforms: readonly UniformEntry[],
    view: View,
    tile: FrameOptions = {},
  ): Promise<ProbeImage> {
    for (const src of tile.pictures ?? []) {
      // A live picture (camera, video) has no frames here: its fallback is drawn, as in the CLI.
      const pic = resolvePicture(parseLiveKey(src)?.fallback ?? src, undefined);
      const base64 = Buffer.from(pic.data.buffer, pic.data.byteOffset, pic.data.byteLength).toString(
        'base64',
      );
      await this.page.evaluate(([s, w, h, b]) => window.kfHarness.picture(s, w, h, b), [
        src,
        pic.width,
        pic.height,
        base64,
      ] as const);
    }
    const frame = {
      pictures: tile.pictures,
      view: [view.center[0], view.center[1], view.scale],
      jitter: [0.5, 0.5],
      resolution: tile.resolution,
      pixelOffset: tile.offset,
      bgAlpha: tile.bgAlpha,
    };
    const out = await this.page.evaluate(([index, u, f]) => window.kfHarness.render(index, u, f), [
      program,
      uniforms,
      frame,
    ] as const);
    const bytes = Buffer.from(out.data, 'base64');
    const data = new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
    return { width: this.width, height: this.height, data: new Float32Array(data), ms: out.ms };
  }

  close(): Promise<void> {
    return this.browser.close();
  }
}

interface Harness {
  init(width: number, height: number): string;
  program(vs: string, fs: string): number;
  render(
    index: number,
    uniforms: readonly UniformEntry[],
    frame: {
      view: number[];
      jitter: number[];
      resolution?: readonly number[];
      pixelOffset?: readonly number[];
      bgAlpha?: number;
      pictures?: readonly string[];
    },
  ): { data: string; ms: number };
  picture(src: string, width: number, height: number, base64: string): void;
  compileCount: number;
}

declare global {
  interface Window {
    kfHarness: Harness;
  }
}
