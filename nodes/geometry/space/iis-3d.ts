/**
 * CPU IIS loop in R³ (paper §4.2; docs/math-3d.md §4): repeatedly apply the first element whose
 * region holds the point, accumulating the conformal factor, until no element moves it (the point
 * has reached the fundamental domain) or the iteration budget is spent.
 */
import { type BoxFold, stepBoxFold } from './box-fold.ts';
import { type CompoundLoxodromic3d, stepCompoundLoxodromic3d } from './compound-loxodromic-3d.ts';
import { type CompoundParabolic3d, stepCompoundParabolic3d } from './compound-parabolic-3d.ts';
import { type Mobius3d, stepMobius3d } from './mobius-3d.ts';
import {
  insideSphere,
  invertInSphere,
  type Mapped,
  type Plane,
  planeSignedDistance,
  reflectInPlane,
  type Sphere,
} from './sphere.ts';
import type { Vec3 } from './vec3.ts';

export type Element3d =
  | { readonly kind: 'sphere-inversion'; readonly sphere: Sphere }
  | { readonly kind: 'plane-reflection'; readonly plane: Plane }
  | { readonly kind: 'mobius-3d'; readonly g: Mobius3d }
  | { readonly kind: 'compound-loxodromic-3d'; readonly g: CompoundLoxodromic3d }
  | { readonly kind: 'compound-parabolic-3d'; readonly g: CompoundParabolic3d }
  | { readonly kind: 'box-fold'; readonly box: BoxFold };

/** One element's step: its map if x lies in its region (ball; moved side of a plane; outside a box), else null. */
export function stepElement3d(e: Element3d, x: Vec3): Mapped | null {
  switch (e.kind) {
    case 'sphere-inversion':
      return insideSphere(e.sphere, x) ? invertInSphere(e.sphere, x) : null;
    case 'plane-reflection':
      return planeSignedDistance(e.plane, x) < 0 ? reflectInPlane(e.plane, x) : null;
    case 'mobius-3d':
      return stepMobius3d(e.g, x);
    case 'compound-loxodromic-3d':
      return stepCompoundLoxodromic3d(e.g, x);
    case 'compound-parabolic-3d':
      return stepCompoundParabolic3d(e.g, x);
    case 'box-fold':
      return stepBoxFold(e.box, x);
  }
}

export interface Iis3dResult {
  /** Number of element applications. */
  readonly depth: number;
  readonly point: Vec3;
  /** Product of the conformal factors: lengths near the start point scale by this into the final point's neighbourhood. */
  readonly factor: number;
  /** True when the point left every region (reached the fundamental domain) within the budget. */
  readonly escaped: boolean;
}

/**
 * Called after each application: the index of the element applied (list order), the point, the
 * accumulated factor and the depth after it (the 3D twin of the 2D loop's observer; "Explain
 * this pixel" records the word with it).
 */
export type Iis3dObserver = (element: number, x: Vec3, factor: number, depth: number) => void;

/**
 * for i < maxIterations: find the first element e (in list order) with x in its region;
 * none → escaped; else x ← e(x), factor ← factor·e's factor, depth += 1.
 */
export function iis3d(
  elements: readonly Element3d[],
  start: Vec3,
  maxIterations: number,
  observe?: Iis3dObserver,
): Iis3dResult {
  let x = start;
  let factor = 1;
  let depth = 0;
  for (let i = 0; i < maxIterations; i++) {
    let moved: Mapped | null = null;
    let applied = -1;
    for (let j = 0; j < elements.length && !moved; j++) {
      moved = stepElement3d(elements[j]!, x);
      applied = j;
    }
    if (!moved) return { depth, point: x, factor, escaped: true };
    x = moved.x;
    factor *= moved.factor;
    depth += 1;
    observe?.(applied, x, factor, depth);
  }
  const stillMoving = elements.some((e) => stepElement3d(e, x) !== null);
  return { depth, point: x, factor, escaped: !stillMoving };
}
