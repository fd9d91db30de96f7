/**
 * Circle inversion (c, r): inside |p−c| < r; σ(p) = c + r²(p−c)/|p−c|²; scale r²/|p−c|².
 * Outer circle inversion: the circle mirror that keeps its inside; it acts on |p−c| > r with the
 * same map (invertState: the centre is never reached, it lies on the kept side).
 * GLSL packing (1 vec4): d0 = (c.x, c.y, r, r²): r² computed once on the CPU
 * (in float64, then rounded like every uniform) rather than every pass of the loop.
 */
import type { InversionElement, OuterInversionElement } from '../../nodes/core/scene.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { glslFunction } from '../glsl/snippet.ts';
import { type ElementRecord, glslStepBlock, type IisState } from './element-kind.ts';

/**
 * The point exactly at an inversion centre maps to ∞ (r²/0): it goes instead to the far point
 * c + (r·G, 0) with scale G², so the run stays finite and the GPU twin does the same (G =
 * CENTRE_GUARD). The guard is two operations with no branch and no choice — SwiftShader pays for an
 * `if` or a `?:` here with about a third of an inversion-heavy frame, and for each further operation
 * with a few per cent (tests/bench/shader-ratio.ts):
 *   k = min(r²/|d|², G²),  σ(p) = c + (d + (r/G, 0))·k      (d = p − c)
 * r²/0 = ∞ becomes G², so the centre lands on c + (r/G)·G² = c + (r·G, 0). Elsewhere the shift
 * (r/G)·k moves the exact image c + d·k by a fraction r/(G·|d|) of its distance from c: 1e-18 at
 * the rim, 1e-16 at |d| = r/100 — below float64 resolution there (dx + r/G rounds back to dx), far
 * below float32's — and it only grows for points within r/100 of the centre, which all land beyond
 * 100·r, far out where the tile is.
 */
export const CENTRE_GUARD = 1e18;
/** r/G as r · (1/G): one multiplication, the same in both twins. */
export const CENTRE_SHIFT = 1 / CENTRE_GUARD;

/** Inverts the state's point in (cx, cy, r) unconditionally; shared by the generator kinds. */
export function invertState(st: IisState, cx: number, cy: number, r: number): void {
  const dx = st.x - cx;
  const dy = st.y - cy;
  const d2 = dx * dx + dy * dy;
  const k = Math.min((r * r) / d2, CENTRE_GUARD * CENTRE_GUARD);
  st.x = cx + (dx + r * CENTRE_SHIFT) * k;
  st.y = cy + dy * k;
  st.s *= k;
}

/**
 * invertOffset(p, s, c, r, r², dx, dy, d²) with (dx, dy) = p − c and d² = dx² + dy² already at
 * hand (the inversion's own side test computed them): k = min(r²/d², G²), p ← c + (dx + r/G, dy)·k,
 * s ← s·k (same operations, same order as invertState above; r²/0 is +∞ in IEEE arithmetic and
 * min(+∞, G²) = G², so the centre goes to c + (r·G, 0)). No branch and no `?:`: see inversion.ts
 * CENTRE_GUARD.
 */
export const invertOffsetGlsl = glslFunction(
  'invertOffset',
  `
void invertOffset(inout vec2 p, inout float s, vec2 c, float r, float r2, float dx, float dy, float d2) {
  float k = min(r2 / d2, ${floatLiteral(CENTRE_GUARD * CENTRE_GUARD)});
  p = vec2(c.x + (dx + r * ${floatLiteral(CENTRE_SHIFT)}) * k, c.y + dy * k);
  s *= k;
}`,
);

/** invertState(p, s, c, r, r²): the GLSL invertState, for the kinds that invert unconditionally. */
export const invertStateGlsl = glslFunction(
  'invertState',
  `
void invertState(inout vec2 p, inout float s, vec2 c, float r, float r2) {
  float dx = p.x - c.x;
  float dy = p.y - c.y;
  invertOffset(p, s, c, r, r2, dx, dy, dx * dx + dy * dy);
}`,
  [invertOffsetGlsl],
);

/**
 * A circle mirror's record, for both sides it can act on: `inner` inversion acts inside the
 * circle (|p−c|² < r²), `outer` inversion outside it (|p−c|² > r²). The two differ only in that
 * comparison and in how NaN falls: the inner test is written as "not outside" (NaN is inverted,
 * as it always was), the outer one as "outside" (NaN falls through); CPU and GLSL do the same.
 */
function circleMirrorRecord<E extends InversionElement | OuterInversionElement>(
  kind: E['kind'],
  glslName: string,
  acts: 'inside' | 'outside',
): ElementRecord<E> {
  const inner = acts === 'inside';
  return {
    kind,
    cpu: {
      step(e, st) {
        const dx = st.x - e.c[0];
        const dy = st.y - e.c[1];
        const d2 = dx * dx + dy * dy;
        const r2 = e.r * e.r;
        if (inner ? d2 >= r2 : !(d2 > r2)) return false;
        invertState(st, e.c[0], e.c[1], e.r);
        st.depth += 1;
        return true;
      },
      inside: (e, x, y) => {
        const d2 = (x - e.c[0]) ** 2 + (y - e.c[1]) ** 2;
        return inner ? d2 < e.r * e.r : d2 > e.r * e.r;
      },
      boundaryDistance: (e, x, y) => Math.abs(Math.hypot(x - e.c[0], y - e.c[1]) - e.r),
    },
    glsl: {
      vec4s: 1,
      pack: (e) => [e.c[0], e.c[1], e.r, e.r * e.r],
      step: glslStepBlock(
        `
float dx = p.x - d0.x;
float dy = p.y - d0.y;
float d2 = dx * dx + dy * dy;
if (${inner ? '!(d2 >= d0.w)' : 'd2 > d0.w'}) {
  invertOffset(p, s, d0.xy, d0.z, d0.w, dx, dy, d2);
  continue;
}`,
        [invertOffsetGlsl],
      ),
      inside: glslFunction(
        `${glslName}Inside`,
        `
bool ${glslName}Inside(vec2 p, vec4 d0) {
  float dx = p.x - d0.x;
  float dy = p.y - d0.y;
  return dx * dx + dy * dy ${inner ? '<' : '>'} d0.w;
}`,
      ),
      boundaryDistance: glslFunction(
        `${glslName}BoundaryDistance`,
        `
float ${glslName}BoundaryDistance(vec2 p, vec4 d0) {
  return abs(length(p - d0.xy) - d0.z);
}`,
      ),
    },
  };
}

export const inversion = circleMirrorRecord<InversionElement>('inversion', 'inversion', 'inside');
export const outerInversion = circleMirrorRecord<OuterInversionElement>(
  'outer-inversion',
  'outerInversion',
  'outside',
);
