/** GLSL twin of glide-reflection.ts. Packing (2 vec4): the strip, see strip-fold.glsl.ts. */
import type { GlideReflectionElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { reflectStateGlsl } from './reflection.glsl.ts';
import { foldCountGlsl, packStrip, stripDistance, stripIndexGlsl, stripInside } from './strip-fold.glsl.ts';

export const glideReflectionGlsl: GlslElementTwin<GlideReflectionElement> = {
  kind: 'glide-reflection',
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
};
