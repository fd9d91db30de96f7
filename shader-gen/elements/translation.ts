/**
 * Translation strip (closed form, docs/math.md): h = (p − q)·n, k = ⌊h/D⌋; tile 0 ≤ h < D; otherwise
 * p ← p − k·t in one go with t = D·n (or the element's oblique `shift`, t·n = D), depth += |k|
 * (the number of single translations by ±t it stands for). Scale 1 (an isometry).
 * GLSL packing (2 vec4): the strip (see strip-fold.ts) with the
 * translation vector t in d1.yz: d0 = (q.x, q.y, n.x, n.y), d1 = (period D, t.x, t.y, 0).
 */
import type { TranslationElement } from '../../nodes/core/scene.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import { type ElementRecord, glslStepBlock } from './element-kind.ts';
import {
  foldCountGlsl,
  packStrip,
  stripBoundaryDistance,
  stripDistance,
  stripIndex,
  stripIndexGlsl,
  stripInside,
} from './strip-fold.ts';

/** The translation vector t: the element's `shift`, or period·n. */
export const translationShift = (e: TranslationElement): Vec2 =>
  e.shift ?? [e.period * e.n[0], e.period * e.n[1]];

export const translation: ElementRecord<TranslationElement> = {
  kind: 'translation',
  cpu: {
    step(e, st) {
      const k = stripIndex(e, st.x, st.y);
      if (k === 0) return false;
      const [tx, ty] = translationShift(e);
      st.x -= k * tx;
      st.y -= k * ty;
      st.depth += Math.abs(k);
      return true;
    },
    inside: (e, x, y) => stripIndex(e, x, y) !== 0,
    boundaryDistance: stripBoundaryDistance,
  },
  glsl: {
    vec4s: 2,
    pack: (e) => {
      const strip = packStrip(e);
      const t = translationShift(e);
      return [...strip.slice(0, 5), t[0], t[1], 0];
    },
    step: glslStepBlock(
      `
float k = stripIndex(d0, d1, p);
if (k != 0.0) {
  p = vec2(p.x - k * d1.y, p.y - k * d1.z);
  depth += foldCount(k) - 1;
  continue;
}`,
      [stripIndexGlsl, foldCountGlsl],
    ),
    inside: stripInside('translation'),
    boundaryDistance: stripDistance('translation'),
  },
};
