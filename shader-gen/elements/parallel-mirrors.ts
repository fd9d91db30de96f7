/**
 * Parallel mirrors h = 0 and h = D (closed form, docs/math.md): the group they generate folds the
 * plane onto the strip 0 ≤ h < D. With k = ⌊h/D⌋ and r = h − kD ∈ [0, D): an even k is a
 * translation by −kD (h ← r), an odd k adds one reflection (h ← D − r). depth += |k|, the number
 * of mirrors crossed; scale 1.
 * GLSL packing (2 vec4): the strip, see strip-fold.ts.
 */
import type { ParallelMirrorsElement } from '../../nodes/core/scene.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';
import {
  foldCountGlsl,
  packStrip,
  stripBoundaryDistance,
  stripDistance,
  stripHeight,
  stripHeightGlsl,
  stripInside,
} from './strip-fold.ts';

export const parallelMirrors: ElementRecord<ParallelMirrorsElement> = {
  kind: 'parallel-mirrors',
  cpu: {
    step(e, st) {
      const D = e.period;
      const h = stripHeight(e, st.x, st.y);
      const k = Math.floor(h / D);
      if (k === 0) return false;
      const r = h - k * D;
      const target = k % 2 === 0 ? r : D - r;
      st.x += (target - h) * e.n[0];
      st.y += (target - h) * e.n[1];
      st.depth += Math.abs(k);
      return true;
    },
    inside: (e, x, y) => Math.floor(stripHeight(e, x, y) / e.period) !== 0,
    boundaryDistance: stripBoundaryDistance,
  },
  glsl: {
    vec4s: 2,
    pack: packStrip,
    step: glslStepBlock(
      `
float D = d1.x;
float h = stripHeight(d0, p);
float k = floor(h / D);
if (k != 0.0) {
  float r = h - k * D;
  float target = mod(k, 2.0) == 0.0 ? r : D - r;
  p = vec2(p.x + (target - h) * d0.z, p.y + (target - h) * d0.w);
  depth += foldCount(k) - 1;
  continue;
}`,
      [stripHeightGlsl, foldCountGlsl],
    ),
    inside: stripInside('parallelMirrors'),
    boundaryDistance: stripDistance('parallelMirrors'),
  },
};
