/** GLSL twin of shader-gen/view.ts: pixel → world and the sub-pixel sample pattern. */
import { sampleOffset } from '../view.ts';
import { floatLiteral } from './literal.ts';
import { glslFunction } from './snippet.ts';

/**
 * pixelToWorld: world = center + ((px + o − W/2)/H · scale, (py + o − H/2)/H · scale), view =
 * (center.x, center.y, scale), size = (W, H); same operations in the same order as the CPU.
 */
export const pixelToWorldGlsl = glslFunction(
  'pixelToWorld',
  `
vec2 pixelToWorld(vec3 view, vec2 size, vec2 px, vec2 o) {
  return vec2(view.x + ((px.x + o.x - size.x / 2.0) / size.y) * view.z,
              view.y + ((px.y + o.y - size.y / 2.0) / size.y) * view.z);
}`,
);

/** The R2 step, read back from the CPU's sampleOffset(1) − 0.5 so the constant has one home. */
const r2 = sampleOffset(1).map((v) => (v - 0.5 + 1) % 1);

/** sampleOffset: k = 0 is the pixel centre; k > 0 follows the R2 sequence fract(0.5 + k·α). */
export const sampleOffsetGlsl = glslFunction(
  'sampleOffset',
  `
vec2 sampleOffset(int k) {
  if (k == 0) return vec2(0.5);
  return fract(vec2(0.5) + float(k) * vec2(${floatLiteral(r2[0])}, ${floatLiteral(r2[1])}));
}`,
);
