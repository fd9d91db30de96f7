/**
 * Rotation of order k about c (closed form, docs/math.md): θ = 2π/k, the tile is the wedge from the
 * unit direction b1 counter-clockwise by θ. With arg ∈ [0, 2π) measured from b1 and
 * m = ⌊arg/θ⌋ (at most k − 1), rotate by −mθ about c; depth += m (the single steps "rotate by −θ"
 * it stands for). The centre itself is in the tile (arg taken as 0). Scale 1.
 * GLSL packing (2 vec4): d0 = (c.x, c.y, b1.x, b1.y),
 * d1 = (order k, cos θ, sin θ, 0) with θ = 2π/k computed on the CPU. atan is approximate on GPUs
 * (errors ~1e-4 in SwiftShader): the wedge edges are where the GPU and the CPU may disagree, which
 * boundaryDistance reports. The turn by −mθ is the m-th power of e^(−iθ) (complex-power.ts),
 * not cos/sin of mθ, so the final point keeps float32 accuracy.
 */
import type { RotationElement } from '../../nodes/core/scene.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { complexPowerGlsl } from './complex-power.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';

/** m = ⌊arg/θ⌋ ∈ [0, k − 1] for the point (dx, dy) relative to the centre. */
export function wedgeIndex(e: RotationElement, dx: number, dy: number): number {
  const [ux, uy] = e.b1;
  let arg = Math.atan2(ux * dy - uy * dx, ux * dx + uy * dy);
  if (arg < 0) arg += 2 * Math.PI;
  return Math.min(e.order - 1, Math.floor((arg * e.order) / (2 * Math.PI)));
}

/** Distance from (dx, dy) (relative to the ray's origin) to the ray in unit direction (ux, uy). */
function rayDistance(dx: number, dy: number, ux: number, uy: number): number {
  const t = dx * ux + dy * uy;
  return t <= 0 ? Math.hypot(dx, dy) : Math.abs(ux * dy - uy * dx);
}

const TWO_PI = floatLiteral(2 * Math.PI);

/** m = ⌊arg·k/2π⌋ ∈ [0, k − 1], arg ∈ [0, 2π) from b1; the centre (atan2(0, 0) = 0) gives 0. */
export const wedgeIndexGlsl = glslFunction(
  'wedgeIndex',
  `
float wedgeIndex(vec4 d0, vec4 d1, float dx, float dy) {
  float cr = d0.z * dy - d0.w * dx;
  float dt = d0.z * dx + d0.w * dy;
  if (cr == 0.0 && dt == 0.0) return 0.0;
  float arg = atan(cr, dt);
  if (arg < 0.0) arg += ${TWO_PI};
  return min(d1.x - 1.0, floor((arg * d1.x) / ${TWO_PI}));
}`,
);

/** Distance from (dx, dy) to the ray from the origin in unit direction u. */
export const rayDistanceGlsl = glslFunction(
  'rayDistance',
  `
float rayDistance(float dx, float dy, float ux, float uy) {
  float t = dx * ux + dy * uy;
  return t <= 0.0 ? length(vec2(dx, dy)) : abs(ux * dy - uy * dx);
}`,
);

export const rotation: ElementRecord<RotationElement> = {
  kind: 'rotation',
  cpu: {
    step(e, st) {
      const dx = st.x - e.c[0];
      const dy = st.y - e.c[1];
      const m = wedgeIndex(e, dx, dy);
      if (m <= 0) return false;
      const t = (-2 * Math.PI * m) / e.order;
      const cos = Math.cos(t);
      const sin = Math.sin(t);
      st.x = e.c[0] + cos * dx - sin * dy;
      st.y = e.c[1] + sin * dx + cos * dy;
      st.depth += m;
      return true;
    },
    inside: (e, x, y) => wedgeIndex(e, x - e.c[0], y - e.c[1]) > 0,
    boundaryDistance(e, x, y) {
      const dx = x - e.c[0];
      const dy = y - e.c[1];
      const t = (2 * Math.PI) / e.order;
      const [ux, uy] = e.b1;
      const vx = Math.cos(t) * ux - Math.sin(t) * uy;
      const vy = Math.sin(t) * ux + Math.cos(t) * uy;
      return Math.min(rayDistance(dx, dy, ux, uy), rayDistance(dx, dy, vx, vy));
    },
  },
  glsl: {
    vec4s: 2,
    pack: (e) => {
      const t = (2 * Math.PI) / e.order;
      return [e.c[0], e.c[1], e.b1[0], e.b1[1], e.order, Math.cos(t), Math.sin(t), 0];
    },
    step: glslStepBlock(
      `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
float m = wedgeIndex(d0, d1, dx, dy);
if (!(m <= 0.0)) {
  vec2 w = complexPower(vec2(d1.y, -d1.z), int(m));
  p = vec2(d0.x + w.x * dx - w.y * dy, d0.y + w.y * dx + w.x * dy);
  depth += max(int(m), 1) - 1; // m ≥ 1 here; NaN (int() undefined) counts 1
  continue;
}`,
      [wedgeIndexGlsl, complexPowerGlsl],
    ),
    inside: glslFunction(
      'rotationInside',
      `
bool rotationInside(vec2 p, vec4 d0, vec4 d1) {
  return wedgeIndex(d0, d1, p.x - d0.x, p.y - d0.y) > 0.0;
}`,
      [wedgeIndexGlsl],
    ),
    boundaryDistance: glslFunction(
      'rotationBoundaryDistance',
      `
float rotationBoundaryDistance(vec2 p, vec4 d0, vec4 d1) {
  float dx = p.x - d0.x;
  float dy = p.y - d0.y;
  float vx = d1.y * d0.z - d1.z * d0.w;
  float vy = d1.z * d0.z + d1.y * d0.w;
  return min(rayDistance(dx, dy, d0.z, d0.w), rayDistance(dx, dy, vx, vy));
}`,
      [rayDistanceGlsl],
    ),
  },
};
