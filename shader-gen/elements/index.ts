/** Every element kind, by kind: the one table the interpreter and the compiler dispatch on. */
import type { SceneElement } from '../../nodes/core/scene.ts';
import type { ElementKind } from './element-kind.ts';
import { glideReflection } from './glide-reflection.ts';
import { inversion } from './inversion.ts';
import { loxodromic } from './loxodromic.ts';
import { mobius } from './mobius.ts';
import { mobiusMatrix } from './mobius-matrix.ts';
import { outerInversion } from './outer-inversion.ts';
import { parallelMirrors } from './parallel-mirrors.ts';
import { reflection } from './reflection.ts';
import { rotation } from './rotation.ts';
import { spiralSimilarity } from './spiral-similarity.ts';
import { translation } from './translation.ts';

type KindTable = { readonly [K in SceneElement['kind']]: ElementKind<Extract<SceneElement, { kind: K }>> };

export const ELEMENT_KINDS: KindTable = {
  inversion,
  'outer-inversion': outerInversion,
  reflection,
  mobius,
  loxodromic,
  'mobius-matrix': mobiusMatrix,
  translation,
  'parallel-mirrors': parallelMirrors,
  'glide-reflection': glideReflection,
  rotation,
  'spiral-similarity': spiralSimilarity,
};

export function elementKind<E extends SceneElement>(e: E): ElementKind<E> {
  return ELEMENT_KINDS[e.kind] as unknown as ElementKind<E>;
}
