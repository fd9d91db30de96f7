/**
 * The Maskit slice in the parameter plane (docs/math.md "The Maskit slice boundary"): the picture's
 * point is μ = x + iy, and the element's inside is where Maskit's group of parameter μ is NOT
 * discrete and free — below the boundary polyline through the cusps μ_{p/q} with q ≤ maxDenominator,
 * taken with period 2 in x and mirrored in y = 0 (μ̄ gives the complex-conjugate group). The
 * verdict is a crossing count: fold x into [−2, 0), and μ is below the polyline when the upward ray
 * from (x, |y|) crosses it an odd number of times (the polyline runs from x = 0 to x = −2).
 * A group that is not discrete has no fundamental domain, so no run of the IIS ever reaches a tile:
 * the step leaves μ where it is and stands for LIMITS.maxIterations steps, which ends the loop with
 * μ still inside, not escaped (the limit colour); μ in the slice is in the tile at depth 0.
 * The CPU half is nodes/geometry/maskit-cusps.ts (the node asks it too); the GLSL below is its twin.
 * GLSL packing (1 vec4): d0 = (maxDenominator, 0, 0, 0); the cusps are one constant array.
 */
import { LIMITS } from '../../nodes/core/limits.ts';
import type { MaskitSliceElement } from '../../nodes/core/scene.ts';
import {
  belowMaskitBoundary,
  fareySequence,
  MASKIT_MAX_DENOMINATOR,
  maskitBoundaryDistance,
  maskitCusps,
} from '../../nodes/geometry/maskit-cusps.ts';
import { floatLiteral } from '../glsl/literal.ts';
import { type GlslFunction, glslFunction } from '../glsl/snippet.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';

/** The number of cusps (Farey fractions in [0, 1] with q ≤ MASKIT_MAX_DENOMINATOR). */
const N = fareySequence(MASKIT_MAX_DENOMINATOR).length;

/**
 * The cusps as a GLSL constant array of (x, y, q). Written on first use (a getter): the cusps take
 * Newton's method to compute, and only a scene with the slice needs them.
 */
const CUSP_ARRAY: GlslFunction = {
  name: 'MASKIT_CUSPS',
  get code() {
    const rows = maskitCusps().map(
      (c) => `  vec3(${floatLiteral(c.mu[0])}, ${floatLiteral(c.mu[1])}, ${floatLiteral(c.q)})`,
    );
    return `const vec3 MASKIT_CUSPS[${N}] = vec3[${N}](\n${rows.join(',\n')}\n);`;
  },
};

const INSIDE = glslFunction(
  'maskitSliceInside',
  `
bool maskitSliceInside(vec2 p, vec4 d0) {
  float fx = p.x - 2.0 * floor(p.x * 0.5 + 1.0);
  float fy = abs(p.y);
  bool below = false;
  vec3 a = MASKIT_CUSPS[0];
  for (int i = 1; i < ${N}; ++i) {
    vec3 b = MASKIT_CUSPS[i];
    if (b.z > d0.x) continue;
    if ((a.x > fx) != (b.x > fx) && a.y + (fx - a.x) * (b.y - a.y) / (b.x - a.x) > fy) below = !below;
    a = b;
  }
  return below;
}`,
  [CUSP_ARRAY],
);

const SEGMENT_DISTANCE = glslFunction(
  'maskitSliceSegment',
  `
float maskitSliceSegment(vec2 p, vec2 a, vec2 b) {
  vec2 d = b - a;
  float t = clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return length(p - a - t * d);
}`,
);

export const maskitSlice: ElementRecord<MaskitSliceElement> = {
  kind: 'maskit-slice',
  cpu: {
    step(e, st) {
      if (!belowMaskitBoundary(st.x, st.y, e.maxDenominator)) return false;
      st.depth += LIMITS.maxIterations;
      return true;
    },
    inside: (e, x, y) => belowMaskitBoundary(x, y, e.maxDenominator),
    boundaryDistance: (e, x, y) => maskitBoundaryDistance(x, y, e.maxDenominator),
  },
  glsl: {
    vec4s: 1,
    pack: (e) => [e.maxDenominator, 0, 0, 0],
    step: glslStepBlock(
      `
if (maskitSliceInside(p, d0)) {
  depth += ${LIMITS.maxIterations - 1};
  continue;
}`,
      [INSIDE],
    ),
    inside: INSIDE,
    boundaryDistance: glslFunction(
      'maskitSliceBoundaryDistance',
      `
float maskitSliceBoundaryDistance(vec2 p, vec4 d0) {
  vec2 f = vec2(p.x - 2.0 * floor(p.x * 0.5 + 1.0), abs(p.y));
  float d = 3.0e38;
  vec2 a = MASKIT_CUSPS[0].xy;
  for (int i = 1; i < ${N}; ++i) {
    vec3 b = MASKIT_CUSPS[i];
    if (b.z > d0.x) continue;
    d = min(d, maskitSliceSegment(f + vec2(-2.0, 0.0), a, b.xy));
    d = min(d, maskitSliceSegment(f, a, b.xy));
    d = min(d, maskitSliceSegment(f + vec2(2.0, 0.0), a, b.xy));
    a = b.xy;
  }
  return d;
}`,
      [CUSP_ARRAY, SEGMENT_DISTANCE],
    ),
  },
};
