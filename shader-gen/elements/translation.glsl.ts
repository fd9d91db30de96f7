/**
 * GLSL twin of translation.ts. Packing (2 vec4): the strip (see strip-fold.glsl.ts) with the
 * translation vector t in d1.yz: d0 = (q.x, q.y, n.x, n.y), d1 = (period D, t.x, t.y, 0).
 */
import type { TranslationElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { foldCountGlsl, packStrip, stripDistance, stripIndexGlsl, stripInside } from './strip-fold.glsl.ts';
import { translationShift } from './translation.ts';

export const translationGlsl: GlslElementTwin<TranslationElement> = {
  kind: 'translation',
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
};
