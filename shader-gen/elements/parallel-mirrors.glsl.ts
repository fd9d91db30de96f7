/** GLSL twin of parallel-mirrors.ts. Packing (2 vec4): the strip, see strip-fold.glsl.ts. */
import type { ParallelMirrorsElement } from '../../nodes/core/scene.ts';
import { type GlslElementTwin, glslStepBlock } from '../glsl/element-twin.ts';
import { foldCountGlsl, packStrip, stripDistance, stripHeightGlsl, stripInside } from './strip-fold.glsl.ts';

export const parallelMirrorsGlsl: GlslElementTwin<ParallelMirrorsElement> = {
  kind: 'parallel-mirrors',
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
};
