/**
 * Every 3D element kind, by kind: the one registry the CPU tracer and the GLSL generator dispatch
 * on (the 3D twin of shader-gen/elements/index.ts). The mapped type makes a kind of Element3d
 * without a record — or a record without either half — fail to type-check.
 */
import type { Element3d } from '../../../nodes/core/scene-3d.ts';
import { boxFold } from './box-fold.ts';
import { compoundLoxodromic3d } from './compound-loxodromic-3d.ts';
import { compoundParabolic3d } from './compound-parabolic-3d.ts';
import type { ElementRecord3d } from './element-3d-kind.ts';
import { mobius3d } from './mobius-3d.ts';
import { planeReflection } from './plane-reflection.ts';
import { sphereInversion } from './sphere-inversion.ts';

export type Element3dKindName = Element3d['kind'];

export type ElementRegistry3d = {
  readonly [K in Element3dKindName]: ElementRecord3d<Extract<Element3d, { kind: K }>>;
};

export const ELEMENTS_3D: ElementRegistry3d = {
  'sphere-inversion': sphereInversion,
  'plane-reflection': planeReflection,
  'mobius-3d': mobius3d,
  'compound-loxodromic-3d': compoundLoxodromic3d,
  'compound-parabolic-3d': compoundParabolic3d,
  'box-fold': boxFold,
};

/** The record of `e`'s kind (the cast is safe by the registry's mapped type). */
export function elementRecord3d<E extends Element3d>(e: E): ElementRecord3d<E> {
  return ELEMENTS_3D[e.kind as Element3dKindName] as unknown as ElementRecord3d<E>;
}
