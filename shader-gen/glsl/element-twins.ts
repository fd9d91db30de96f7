/**
 * Every element kind's GLSL twin, by kind: the table the compiler dispatches on (the GLSL side of
 * elements/index.ts). The mapped type makes a new kind in the Scene union fail to type-check until
 * its twin is added here.
 */
import type { SceneElement } from '../../nodes/core/scene.ts';
import { glideReflectionGlsl } from '../elements/glide-reflection.glsl.ts';
import { inversionGlsl } from '../elements/inversion.glsl.ts';
import { loxodromicGlsl } from '../elements/loxodromic.glsl.ts';
import { mobiusGlsl } from '../elements/mobius.glsl.ts';
import { mobiusMatrixGlsl } from '../elements/mobius-matrix.glsl.ts';
import { outerInversionGlsl } from '../elements/outer-inversion.glsl.ts';
import { parallelMirrorsGlsl } from '../elements/parallel-mirrors.glsl.ts';
import { reflectionGlsl } from '../elements/reflection.glsl.ts';
import { rotationGlsl } from '../elements/rotation.glsl.ts';
import { spiralSimilarityGlsl } from '../elements/spiral-similarity.glsl.ts';
import { translationGlsl } from '../elements/translation.glsl.ts';
import type { GlslElementTwin } from './element-twin.ts';

type TwinTable = {
  readonly [K in SceneElement['kind']]: GlslElementTwin<Extract<SceneElement, { kind: K }>>;
};

export const GLSL_TWINS: TwinTable = {
  inversion: inversionGlsl,
  'outer-inversion': outerInversionGlsl,
  reflection: reflectionGlsl,
  mobius: mobiusGlsl,
  loxodromic: loxodromicGlsl,
  'mobius-matrix': mobiusMatrixGlsl,
  translation: translationGlsl,
  'parallel-mirrors': parallelMirrorsGlsl,
  'glide-reflection': glideReflectionGlsl,
  rotation: rotationGlsl,
  'spiral-similarity': spiralSimilarityGlsl,
};

export function glslTwin<E extends SceneElement>(e: E): GlslElementTwin<E> {
  return GLSL_TWINS[e.kind] as unknown as GlslElementTwin<E>;
}
