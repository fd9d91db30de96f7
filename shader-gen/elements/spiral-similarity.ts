/**
 * Spiral similarity about c (closed form, docs/math.md): the composition of the reflections in the
 * lines through c at angles 0 and φ (a rotation by 2φ) and the inversions in the circles r1 then
 * r2 about c (a scaling by λ = (r2/r1)²): g(p) = c + λ R_2φ (p − c). Tile: the annulus
 * r1 ≤ |p − c| < r1·λ = r2²/r1. With m = ⌊log(|p − c|/r1)/log λ⌋, apply g^(−m) at once:
 * p ← c + λ^(−m) R_(−2mφ) (p − c), scale ×λ^(−m) (the conformal factor of g is λ), depth += |m|.
 * The centre is the fixed point (the limit set): it never reaches the tile.
 * GLSL packing (2 vec4): d0 = (c.x, c.y, r1, r2),
 * d1 = (angle φ, cos 2φ, sin 2φ, 0). log is approximate on GPUs: the annulus circles are where the
 * GPU and the CPU may disagree, which boundaryDistance reports. The fold g^(−m) multiplies p − c by
 * w^|m| with the one-step multiplier w = e^(−2iφ)/λ (m > 0) or λe^(2iφ) (m < 0), by
 * complex-power.ts rather than pow/cos/sin, so the final point keeps float32 accuracy; the
 * scale λ^(−m) is |w^|m||.
 */
import type { SpiralSimilarityElement } from '../../nodes/core/scene.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { complexPowerGlsl } from './complex-power.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';
import { foldCountGlsl } from './strip-fold.ts';

/** λ = (r2/r1)², the scaling of one step. */
export function spiralRatio(e: SpiralSimilarityElement): number {
  const t = e.r2 / e.r1;
  return t * t;
}

/** m = ⌊log(ρ/r1)/log λ⌋ for ρ = |p − c| (−∞ at the centre). */
const annulusIndex = (e: SpiralSimilarityElement, rho: number): number =>
  Math.floor(Math.log(rho / e.r1) / Math.log(spiralRatio(e)));

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

export const spiralSimilarity: ElementRecord<SpiralSimilarityElement> = {
  kind: 'spiral-similarity',
  cpu: {
    step(e, st) {
      const dx = st.x - e.c[0];
      const dy = st.y - e.c[1];
      const rho = Math.hypot(dx, dy);
      if (rho === 0) {
        st.depth += 1; // the fixed point: one step at a time until maxIterations (not escaped)
        return true;
      }
      const m = annulusIndex(e, rho);
      if (m === 0) return false;
      const k = spiralRatio(e) ** -m;
      const t = -2 * m * e.angle;
      const cos = Math.cos(t) * k;
      const sin = Math.sin(t) * k;
      st.x = e.c[0] + cos * dx - sin * dy;
      st.y = e.c[1] + sin * dx + cos * dy;
      st.s *= k;
      st.depth += Math.abs(m);
      return true;
    },
    inside: (e, x, y) => annulusIndex(e, Math.hypot(x - e.c[0], y - e.c[1])) !== 0,
    boundaryDistance(e, x, y) {
      const rho = Math.hypot(x - e.c[0], y - e.c[1]);
      return Math.min(Math.abs(rho - e.r1), Math.abs(rho - e.r1 * spiralRatio(e)));
    },
  },
  glsl: {
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
  },
};
