/**
 * The sRGB transfer function (IEC 61966-2-1), the one place that states it. Colours in documents
 * are sRGB in [0, 1]; shading and blending happen in linear light. Used by the CPU colouring
 * (colour.ts), pictures (picture.ts), seeds (seeds.ts), the raster's 8-bit output and the shader
 * generator, which folds constant colours to linear light here instead of per pixel on the GPU.
 */
import type { Color } from '../nodes/core/values.ts';

export type Rgb = [number, number, number];

/** Decoding: c ≤ 0.04045 ? c/12.92 : ((c + 0.055)/1.055)^2.4. */
export const srgbToLinear = (c: number): number => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);

/** Encoding: c ≤ 0.0031308 ? 12.92c : 1.055c^(1/2.4) − 0.055. */
export const linearToSrgb = (c: number): number =>
  c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;

/** A whole sRGB colour decoded to linear light, channel by channel. */
export const toLinear = (c: Color): Rgb => [srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])];
