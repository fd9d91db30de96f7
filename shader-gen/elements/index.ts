/**
 * Every element kind, by kind: the one registry the interpreter and the compiler dispatch on. Each
 * kind is one module (shader-gen/elements/<kind>.ts) exporting one record with its CPU step and its
 * GLSL twin. The mapped type makes a kind of the Scene union without a record here — or a record
 * without either half — fail to type-check.
 */
import type { SceneElement } from '../../nodes/core/scene.ts';
import type { ElementRecord } from './element-kind.ts';
import { glideReflection } from './glide-reflection.ts';
import { inversion, outerInversion } from './inversion.ts';
import { loxodromic } from './loxodromic.ts';
import { maskit } from './maskit.ts';
import { maskitSlice } from './maskit-slice.ts';
import { mobius } from './mobius.ts';
import { mobiusMatrix } from './mobius-matrix.ts';
import { parallelMirrors } from './parallel-mirrors.ts';
import { reflection } from './reflection.ts';
import { rotation } from './rotation.ts';
import { spiralSimilarity } from './spiral-similarity.ts';
import { translation } from './translation.ts';

/** The name of an element kind: the `kind` tag of the Scene's element union. */
export type ElementKindName = SceneElement['kind'];

/** One record per kind, typed by its own element. */
export type ElementRegistry = {
  readonly [K in ElementKindName]: ElementRecord<Extract<SceneElement, { kind: K }>>;
};

export const ELEMENTS: ElementRegistry = {
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
  maskit,
  'maskit-slice': maskitSlice,
};

/** The record of `e`'s kind (one lookup; the cast is safe by the registry's mapped type). */
export function elementRecord<E extends SceneElement>(e: E): ElementRecord<E> {
  return ELEMENTS[e.kind as ElementKindName] as unknown as ElementRecord<E>;
}
