/**
 * Pictures on the CPU: the built-in procedural picture, and bilinear sampling in linear light with
 * repeat wrapping — what an SRGB8_ALPHA8 texture with LINEAR filtering and REPEAT wrap gives on
 * the GPU (texels decoded to linear, then filtered). The GLSL side is `textureLod(u_imageN, uv, 0)`.
 */
import { BUILTIN_PICTURE } from '../nodes/core/values.ts';
import { type Rgb, srgbToLinear } from './srgb.ts';

/** Decoded pixels: RGBA, 8-bit sRGB, row 0 at the top (PNG order; also the texture's v = 0). */
export interface DecodedPicture {
  readonly width: number;
  readonly height: number;
  readonly data: Uint8Array | Uint8ClampedArray;
}

/** Pictures by `src`, decoded by the caller (nodes stay pure; the CLI and the app decode). */
export type PictureMap = ReadonlyMap<string, DecodedPicture>;

const smoothstep = (a: number, b: number, x: number) => {
  const t = Math.min(1, Math.max(0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
};
const mix = (a: number, b: number, t: number) => a + (b - a) * t;

/**
 * The built-in picture (256², drawn here so CPU and GPU get the same texels): a 4 × 4 checker of
 * warm and cool tones that lighten towards the top, a white arrow pointing up (+y) and a red dot in
 * the top-right corner, so every copy shows its orientation and handedness. Edges are smoothed
 * over about 2 texels so bilinear sampling stays close between float32 and float64.
 */
function drawBuiltinPicture(): DecodedPicture {
  const { width, height } = BUILTIN_PICTURE;
  const data = new Uint8ClampedArray(width * height * 4);
  for (let row = 0; row < height; row++) {
    for (let col = 0; col < width; col++) {
      // (x, y) in [−1, 1]², y up.
      const x = ((col + 0.5) / width) * 2 - 1;
      const y = 1 - ((row + 0.5) / height) * 2;
      const aa = 4 / width;
      const cx = Math.sin(x * 2 * Math.PI);
      const cy = Math.sin(y * 2 * Math.PI);
      const checker = smoothstep(-aa * 6, aa * 6, cx * cy);
      const lift = 0.35 + 0.3 * (y + 1);
      let r = mix(0.15, 0.95, checker) * lift + 0.05;
      let g = mix(0.35, 0.6, checker) * lift;
      let b = mix(0.8, 0.2, checker) * lift;
      // Arrow: a shaft |x| < 0.12 for y in [−0.7, 0.2] and a head: the triangle above it.
      const shaft = Math.min(smoothstep(-aa, aa, 0.12 - Math.abs(x)), smoothstep(-aa, aa, y + 0.7));
      const inShaft = shaft * smoothstep(-aa, aa, 0.25 - y);
      const head = Math.min(smoothstep(-aa, aa, 0.7 - y - Math.abs(x) * 1.3), smoothstep(-aa, aa, y - 0.15));
      const arrow = Math.max(inShaft, head);
      r = mix(r, 1, arrow);
      g = mix(g, 1, arrow);
      b = mix(b, 0.95, arrow);
      const dot = smoothstep(-aa, aa, 0.14 - Math.hypot(x - 0.72, y - 0.72));
      r = mix(r, 0.9, dot);
      g = mix(g, 0.1, dot);
      b = mix(b, 0.12, dot);
      const o = (row * width + col) * 4;
      data[o] = Math.round(Math.min(1, r) * 255);
      data[o + 1] = Math.round(Math.min(1, g) * 255);
      data[o + 2] = Math.round(Math.min(1, b) * 255);
      data[o + 3] = 255;
    }
  }
  return { width, height, data };
}

let builtin: DecodedPicture | null = null;
/** The built-in picture's pixels (drawn once). */
export function builtinPicture(): DecodedPicture {
  builtin ??= drawBuiltinPicture();
  return builtin;
}

/** The pixels of `src`: the built-in picture, or the caller's decoded one (else an error that says so). */
export function resolvePicture(src: string, pictures: PictureMap | undefined): DecodedPicture {
  if (src === BUILTIN_PICTURE.src) return builtinPicture();
  const found = pictures?.get(src);
  if (!found) {
    const shown = src.length > 40 ? `${src.slice(0, 40)}…` : src;
    throw new Error(`picture "${shown}" is not decoded: pass its pixels in the raster's \`pictures\``);
  }
  return found;
}

/** Texels decoded to linear light once per picture (what an SRGB8 texture stores for filtering). */
const linearCache = new WeakMap<DecodedPicture, Float32Array>();
function linearTexels(pic: DecodedPicture): Float32Array {
  let lin = linearCache.get(pic);
  if (!lin) {
    const lut = Array.from({ length: 256 }, (_, i) => srgbToLinear(i / 255));
    lin = new Float32Array(pic.width * pic.height * 3);
    for (let i = 0, n = pic.width * pic.height; i < n; i++) {
      lin[i * 3] = lut[pic.data[i * 4]];
      lin[i * 3 + 1] = lut[pic.data[i * 4 + 1]];
      lin[i * 3 + 2] = lut[pic.data[i * 4 + 2]];
    }
    linearCache.set(pic, lin);
  }
  return lin;
}

const wrap = (i: number, n: number) => ((i % n) + n) % n;

/**
 * Bilinear sample at texture coordinates (u, v) (v = 0 at the top row), REPEAT wrap, in linear
 * light: x = u·W − ½, i = ⌊x⌋, f = x − i; blend texels i and i+1 (mod W) by f, likewise in y.
 */
export function samplePicture(pic: DecodedPicture, u: number, v: number): Rgb {
  const lin = linearTexels(pic);
  const x = u * pic.width - 0.5;
  const y = v * pic.height - 0.5;
  const x0 = Math.floor(x);
  const y0 = Math.floor(y);
  const fx = x - x0;
  const fy = y - y0;
  const c0 = wrap(x0, pic.width);
  const c1 = wrap(x0 + 1, pic.width);
  const r0 = wrap(y0, pic.height) * pic.width;
  const r1 = wrap(y0 + 1, pic.height) * pic.width;
  const out: Rgb = [0, 0, 0];
  for (let k = 0; k < 3; k++) {
    const top = lin[(r0 + c0) * 3 + k] * (1 - fx) + lin[(r0 + c1) * 3 + k] * fx;
    const bottom = lin[(r1 + c0) * 3 + k] * (1 - fx) + lin[(r1 + c1) * 3 + k] * fx;
    out[k] = top * (1 - fy) + bottom * fy;
  }
  return out;
}
