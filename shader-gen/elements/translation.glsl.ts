/** GLSL twin of translation.ts. Packing (2 vec4): the strip, see strip-fold.glsl.ts. */
import type { TranslationElement } from '../../nodes/core/scene.ts';
import type { GlslElementTwin } from '../glsl/element-twin.ts';
import { glslFunction } from '../glsl/snippet.ts';
import {
  foldCountGlsl,
  packStrip,
  STRIP_ARGS,
  stripDistance,
  stripIndexGlsl,
  stripInside,
} from './strip-fold.glsl.ts';

export const translationGlsl: GlslElementTwin<TranslationElement> = {
  kind: 'translation',
  vec4s: 2,
  pack: packStrip,
  step: glslFunction(
    'translationStep',
    `
bool translationStep(inout vec2 p, inout float s, inout int depth, ${STRIP_ARGS}) {
  float k = stripIndex(d0, d1, p);
  if (k == 0.0) return false;
  p = vec2(p.x - k * d1.x * d0.z, p.y - k * d1.x * d0.w);
  depth += foldCount(k);
  return true;
}`,
    [stripIndexGlsl, foldCountGlsl],
  ),
  inside: stripInside('translation'),
  boundaryDistance: stripDistance('translation'),
};
