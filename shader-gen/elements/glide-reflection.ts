/**
 * Glide reflection along the axis through q in direction n, period D (closed form, docs/math.md): the
 * glide is "translate by D·n, then reflect in the axis". With k = ⌊h/D⌋, h = (p − q)·n: translate
 * by −kD·n into the tile 0 ≤ h < D and, when k is odd, reflect across the axis (normal perp(n)).
 * depth += |k|; scale 1.
 * GLSL packing (2 vec4): the strip, see strip-fold.ts.
 */
import type { GlideReflectionElement } from '../../nodes/core/scene.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';
import { reflectState, reflectStateGlsl } from './reflection.ts';
import {
  foldCountGlsl,
  packStrip,
  stripBoundaryDistance,
  stripDistance,
  stripIndex,
  stripIndexGlsl,
  stripInside,
} from './strip-fold.ts';

export const glideReflection: ElementRecord<GlideReflectionElement> = {
  kind: 'glide-reflection',
  cpu: {
    step(e, st) {
      const k = stripIndex(e, st.x, st.y);
      if (k === 0) return false;
      st.x -= k * e.period * e.n[0];
      st.y -= k * e.period * e.n[1];
      // The axis is the line through q along n: its normal is perp(n) = (−n_y, n_x).
      if (k % 2 !== 0) reflectState(st, e.q[0], e.q[1], -e.n[1], e.n[0]);
      st.depth += Math.abs(k);
      return true;
    },
    inside: (e, x, y) => stripIndex(e, x, y) !== 0,
    boundaryDistance: stripBoundaryDistance,
  },
  glsl: {
    vec4s: 2,
    pack: packStrip,
    step: glslStepBlock(
      `
float k = stripIndex(d0, d1, p);
if (k != 0.0) {
  p = vec2(p.x - k * d1.x * d0.z, p.y - k * d1.x * d0.w);
  // The axis is the line through q along n: its normal is perp(n) = (−n_y, n_x).
  if (mod(k, 2.0) != 0.0) reflectState(p, d0.xy, vec2(-d0.w, d0.z));
  depth += foldCount(k) - 1;
  continue;
}`,
      [stripIndexGlsl, reflectStateGlsl, foldCountGlsl],
    ),
    inside: stripInside('glideReflection'),
    boundaryDistance: stripDistance('glideReflection'),
  },
};
