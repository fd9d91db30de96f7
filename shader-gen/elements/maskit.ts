/**
 * The Maskit group's step (docs/math.md "The Maskit slice"), Jos Leys's method as Kleinflow runs it:
 * inside the strip 0 < y < v (μ = u + iv), take the nearest isometric circle — |z − 2k| = 1 of
 * a(z) = μ + 1/z, k = ⌊x/2 + ½⌋, or |z − μ − 2m| = 1 of a⁻¹(z) = 1/(z − μ), m = ⌊(x − u)/2 + ½⌋
 * (each folded by b(z) = z + 2 at once) — and when z lies inside it apply a∘b⁻ᵏ: z ← μ + 1/(z − 2k),
 * scale 1/|z − 2k|², or b⁻ᵐ∘a⁻¹ shifted: z ← 1/(z − μ − 2m), scale 1/|z − μ − 2m|²; depth + 1. The
 * nearer circle has the larger factor, so in the lens where they overlap the step that magnifies
 * most wins (a tie goes to a). Outside the strip (the two half-planes, round disks of the regular
 * set) and outside every circle nothing applies: the point is in the tile.
 * GLSL packing (1 vec4): d0 = (u, v, 0, 0).
 */
import type { MaskitElement } from '../../nodes/core/scene.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';

/**
 * The squared distances q0, q1 are kept ≥ Q_MIN: a point within 10⁻¹⁵ of a centre (a cusp of the
 * limit set, on the strip's edge) would divide by 0, and in float32 |z − c|² underflows to 0 below
 * 10⁻¹⁹; both sides clamp alike, so such a point stays near the limit set instead of becoming NaN.
 */
export const Q_MIN = 1e-30;

/** The offsets from z to the nearest centre of each family: (x − 2k, y) and (x − u − 2m, y − v). */
function offsets(e: MaskitElement, x: number, y: number) {
  const [u, v] = e.mu;
  const dx0 = x - 2 * Math.floor(x * 0.5 + 0.5);
  const dx1 = x - u - 2 * Math.floor((x - u) * 0.5 + 0.5);
  const dy1 = y - v;
  return {
    dx0,
    dx1,
    dy1,
    q0: Math.max(dx0 * dx0 + y * y, Q_MIN),
    q1: Math.max(dx1 * dx1 + dy1 * dy1, Q_MIN),
  };
}

const inStrip = (e: MaskitElement, y: number) => y > 0 && y < e.mu[1];

export const maskit: ElementRecord<MaskitElement> = {
  kind: 'maskit',
  cpu: {
    step(e, st) {
      if (!inStrip(e, st.y)) return false;
      const { dx0, dx1, dy1, q0, q1 } = offsets(e, st.x, st.y);
      if (q0 <= q1 && q0 < 1) {
        // μ + 1/w with w = (dx0, y): 1/w = (dx0, −y)/|w|².
        st.x = e.mu[0] + dx0 / q0;
        st.y = e.mu[1] - st.y / q0;
        st.s /= q0;
      } else if (q1 < q0 && q1 < 1) {
        st.x = dx1 / q1;
        st.y = -dy1 / q1;
        st.s /= q1;
      } else return false;
      st.depth += 1;
      return true;
    },
    inside(e, x, y) {
      if (!inStrip(e, y)) return false;
      const { q0, q1 } = offsets(e, x, y);
      return Math.min(q0, q1) < 1;
    },
    /**
     * A lower bound of the distance to the boundary of the inside (strip ∩ circles) and, where the
     * circles overlap, to the line of equal distance between their centres, where the choice of
     * step changes (|q0 − q1| / (2|c1 − c0|)). In the strip: the circles, and the strip's lines
     * only inside a circle; outside the strip: the larger of the distance to the strip and to the
     * union of the circles (0 inside one).
     */
    boundaryDistance(e, x, y) {
      const { dx0, dx1, dy1, q0, q1 } = offsets(e, x, y);
      const strip = Math.min(Math.abs(y), Math.abs(dy1));
      const circles = Math.min(Math.abs(Math.sqrt(q0) - 1), Math.abs(Math.sqrt(q1) - 1));
      if (!inStrip(e, y)) return Math.max(strip, Math.min(q0, q1) < 1 ? 0 : Math.sqrt(Math.min(q0, q1)) - 1);
      let d = Math.min(q0, q1) < 1 ? Math.min(strip, circles) : circles;
      if (q0 < 1 && q1 < 1) d = Math.min(d, Math.abs(q0 - q1) / (2 * Math.hypot(dx0 - dx1, e.mu[1])));
      return d;
    },
  },
  glsl: {
    vec4s: 1,
    pack: (e) => [e.mu[0], e.mu[1], 0, 0],
    step: glslStepBlock(
      `
if (p.y > 0.0 && p.y < d0.y) {
  float dx0 = p.x - 2.0 * floor(p.x * 0.5 + 0.5);
  float dx1 = p.x - d0.x - 2.0 * floor((p.x - d0.x) * 0.5 + 0.5);
  float dy1 = p.y - d0.y;
  float q0 = max(dx0 * dx0 + p.y * p.y, ${floatLiteral(Q_MIN)});
  float q1 = max(dx1 * dx1 + dy1 * dy1, ${floatLiteral(Q_MIN)});
  if (q0 <= q1 && q0 < 1.0) {
    p = vec2(d0.x + dx0 / q0, d0.y - p.y / q0);
    s /= q0;
    continue;
  } else if (q1 < q0 && q1 < 1.0) {
    p = vec2(dx1 / q1, -dy1 / q1);
    s /= q1;
    continue;
  }
}`,
    ),
    inside: glslFunction(
      'maskitInside',
      `
bool maskitInside(vec2 p, vec4 d0) {
  if (!(p.y > 0.0 && p.y < d0.y)) return false;
  float dx0 = p.x - 2.0 * floor(p.x * 0.5 + 0.5);
  float dx1 = p.x - d0.x - 2.0 * floor((p.x - d0.x) * 0.5 + 0.5);
  float dy1 = p.y - d0.y;
  return min(dx0 * dx0 + p.y * p.y, dx1 * dx1 + dy1 * dy1) < 1.0;
}`,
    ),
    boundaryDistance: glslFunction(
      'maskitBoundaryDistance',
      `
float maskitBoundaryDistance(vec2 p, vec4 d0) {
  float dx0 = p.x - 2.0 * floor(p.x * 0.5 + 0.5);
  float dx1 = p.x - d0.x - 2.0 * floor((p.x - d0.x) * 0.5 + 0.5);
  float dy1 = p.y - d0.y;
  float q0 = max(dx0 * dx0 + p.y * p.y, ${floatLiteral(Q_MIN)});
  float q1 = max(dx1 * dx1 + dy1 * dy1, ${floatLiteral(Q_MIN)});
  float strip = min(abs(p.y), abs(dy1));
  float circles = min(abs(sqrt(q0) - 1.0), abs(sqrt(q1) - 1.0));
  if (!(p.y > 0.0 && p.y < d0.y)) return max(strip, min(q0, q1) < 1.0 ? 0.0 : sqrt(min(q0, q1)) - 1.0);
  float d = min(q0, q1) < 1.0 ? min(strip, circles) : circles;
  if (q0 < 1.0 && q1 < 1.0) d = min(d, abs(q0 - q1) / (2.0 * length(vec2(dx0 - dx1, d0.y))));
  return d;
}`,
    ),
  },
};
