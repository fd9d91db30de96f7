/**
 * GLSL helper for the closed-form turning kinds (rotation, spiral similarity): the n-th power of a
 * complex multiplier by square-and-multiply. The CPU halves call cos/sin/pow of the folded angle in
 * float64; on GPUs those built-ins are approximate (errors near 1e-4 measured in SwiftShader), so
 * the GPU turns by m steps with only + − × on the packed one-step multiplier (cos, sin computed on
 * the CPU): an error of a few float32 ulps per multiplication, O(log m) of them.
 */
import { glslFunction } from '../glsl/snippet.ts';

/** w^n for n ≥ 0 (w = (re, im)): binary exponentiation, (a + ib)(c + id) = (ac − bd) + i(ad + bc). */
export const complexPowerGlsl = glslFunction(
  'complexPower',
  `
vec2 complexPower(vec2 w, int n) {
  vec2 result = vec2(1.0, 0.0);
  vec2 base = w;
  for (int k = n; k > 0; k /= 2) {
    if (k % 2 == 1) result = vec2(result.x * base.x - result.y * base.y, result.x * base.y + result.y * base.x);
    base = vec2(base.x * base.x - base.y * base.y, 2.0 * base.x * base.y);
  }
  return result;
}`,
);
