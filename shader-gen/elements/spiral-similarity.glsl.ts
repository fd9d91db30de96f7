/**
 * GLSL twin of spiral-similarity.ts. Packing (2 vec4): d0 = (c.x, c.y, r1, r2),
 * d1 = (angle φ, cos 2φ, sin 2φ, 0). log is approximate on GPUs: the annulus circles are where the
 * GPU and the CPU may disagree, which boundaryDistance reports. The fold g^(−m) multiplies p − c by
 * w^|m| with the one-step multiplier w = e^(−2iφ)/λ (m > 0) or λe^(2iφ) (m < 0), by
 * complex-power.glsl.ts rather than pow/cos/sin, so the final point keeps float32 accuracy; the
 * scale λ^(−m) is |w^|m||.
 */
import type { SpiralSimilarityElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { complexPowerGlsl } from './complex-power.glsl.ts';
import { foldCountGlsl } from './strip-fold.glsl.ts';

/** λ = (r2/r1)². */
export const spiralRatioGlsl = glslFunction(
  'spiralRatio',
  `
float spiralRatio(vec4 d0) {
  float q = d0.w / d0.z;
  return q * q;
}`,
);

/** m = ⌊log(ρ/r1)/log λ⌋; the centre (ρ = 0, log 0 = −∞ on the CPU) is never in the tile. */
export const annulusIndexGlsl = glslFunction(
  'annulusIndex',
  `
float annulusIndex(vec4 d0, float rho) {
  if (rho == 0.0) return -1.0e9;
  return floor(log(rho / d0.z) / log(spiralRatio(d0)));
}`,
  [spiralRatioGlsl],
);

export const spiralSimilarityGlsl: GlslElementTwin<SpiralSimilarityElement> = {
  kind: 'spiral-similarity',
  vec4s: 2,
  pack: (e) => [e.c[0], e.c[1], e.r1, e.r2, e.angle, Math.cos(2 * e.angle), Math.sin(2 * e.angle), 0],
  step: glslStepBlock(
    `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
float rho = length(vec2(dx, dy));
if (rho == 0.0) {
  continue; // the fixed point: one step at a time until maxIterations (not escaped)
}
float m = annulusIndex(d0, rho);
if (m != 0.0) {
  float lambda = spiralRatio(d0);
  vec2 w = m > 0.0 ? vec2(d1.y, -d1.z) / lambda : vec2(d1.y, d1.z) * lambda;
  vec2 wm = complexPower(w, foldCount(m));
  p = vec2(d0.x + wm.x * dx - wm.y * dy, d0.y + wm.y * dx + wm.x * dy);
  s *= length(wm);
  depth += foldCount(m) - 1;
  continue;
}`,
    [annulusIndexGlsl, spiralRatioGlsl, foldCountGlsl, complexPowerGlsl],
  ),
  inside: glslFunction(
    'spiralSimilarityInside',
    `
bool spiralSimilarityInside(vec2 p, vec4 d0, vec4 d1) {
  return annulusIndex(d0, length(p - d0.xy)) != 0.0;
}`,
    [annulusIndexGlsl],
  ),
  boundaryDistance: glslFunction(
    'spiralSimilarityBoundaryDistance',
    `
float spiralSimilarityBoundaryDistance(vec2 p, vec4 d0, vec4 d1) {
  float rho = length(p - d0.xy);
  return min(abs(rho - d0.z), abs(rho - d0.z * spiralRatio(d0)));
}`,
    [spiralRatioGlsl],
  ),
};
