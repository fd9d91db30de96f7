/**
 * The limit set of a two-generator quaternion Kleinian group by depth-first search of the reduced
 * words (Indra's Pearls' algorithm, run in R̂³; docs/math-3d.md "Quaternion Kleinian groups").
 * Letters 0, 1, 2, 3 = a, b, A, B (the inverse of letter t is t + 2 mod 4). A word w ending in t
 * carries three points: w applied to the attracting fixed points of the "repetends" of t,
 *   t₊ = g(t+1) g(t+2) g(t+3) g(t),   g(t),   t₋ = g(t−1) g(t−2) g(t−3) g(t)
 * (the two commutators ending in t, and t itself). When those points are within ε of each other the
 * branch is a leaf and its points are limit points. ε is `leafPx` pixels at the point's depth, so
 * the search stops at the resolution the camera sees. Like the plane's search (shader-gen/figures/
 * limit-dfs.ts) it has a word cap and a depth cap, and says when either stopped it.
 */

import type { LimitSet3d } from '../../nodes/core/limit-set-3d.ts';
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import {
  attractingFixedPoint,
  type QMatrix,
  type QPoint,
  qmApply,
  qmInverse,
  qmMul,
  qmScale,
  qmSize,
  qPointToSpace,
} from '../../nodes/geometry/space/quaternion-mobius.ts';
import { dist3, dot3, sub3, type Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { cameraBasis, pixelAngle } from './camera-3d.ts';

export interface LimitPoint3d {
  readonly at: Vec3;
  /** The first letter of its word (0…3 = a, b, A, B), for colour. */
  readonly letter: number;
}

export interface LimitSearch3d {
  readonly points: readonly LimitPoint3d[];
  readonly words: number;
  readonly leaves: number;
  /** Why the search drew only part of the limit set, when it did. */
  readonly capped?: string;
}

/** The most points one search emits (three per leaf). */
export const MAX_LIMIT_POINTS_3D = 600_000;

interface Branch {
  readonly word: QMatrix;
  readonly last: number;
  readonly first: number;
  readonly depth: number;
}

const mod4 = (n: number) => ((n % 4) + 4) % 4;

/** The four letters a, b, A, B and, per letter, its repetends' attracting fixed points. */
export function lettersAndRepetends(generators: readonly [QMatrix, QMatrix]): {
  gens: QMatrix[];
  fixed: QPoint[][];
} {
  const [a, b] = generators;
  const gens = [a, b, qmInverse(a), qmInverse(b)];
  const product = (letters: number[]) =>
    letters.slice(1).reduce((m, t) => qmMul(m, gens[mod4(t)]!), gens[mod4(letters[0]!)]!);
  const fixed = gens.map((g, t) => [
    attractingFixedPoint(product([t + 1, t + 2, t + 3, t])),
    attractingFixedPoint(g),
    attractingFixedPoint(product([t - 1, t - 2, t - 3, t])),
  ]);
  return { gens, fixed };
}

/** How far from the camera's target the search keeps branches: the view's half-width, doubled. */
function viewRadius(camera: Camera3d, aspect: number): number {
  const b = cameraBasis(camera);
  return 2 * dist3(camera.position, camera.target) * b.tanHalf * Math.max(1, aspect);
}

/**
 * The limit set's points seen by `camera` in a width × height picture. Children are visited in the
 * cyclic order after the inverse of the last letter, so leaves come out along the limit set.
 */
export function limitSetSearch3d(
  set: LimitSet3d,
  camera: Camera3d,
  width: number,
  height: number,
): LimitSearch3d {
  const { gens, fixed } = lettersAndRepetends(set.generators);
  const basis = cameraBasis(camera);
  const perPixel = pixelAngle(basis, height) * Math.max(set.leafPx, 1e-3);
  const centre = camera.target;
  const reach = viewRadius(camera, width / height);
  const points: LimitPoint3d[] = [];
  let words = 0;
  let leaves = 0;
  let capped: string | undefined;
  const stack: Branch[] = [];
  for (let t = 3; t >= 0; t--) stack.push({ word: gens[t]!, last: t, first: t, depth: 1 });
  while (stack.length > 0) {
    const br = stack.pop() as Branch;
    if (++words > set.maxWords) {
      capped = `the search stopped at ${set.maxWords} words: raise "max words" or "leaf size", or it draws only part of the limit set`;
      break;
    }
    const ends = fixed[br.last]!.map((f) => qPointToSpace(qmApply(br.word, f)));
    const finite = ends.every((p) => p !== null) ? (ends as Vec3[]) : null;
    if (finite) {
      const spread = Math.max(dist3(finite[0]!, finite[1]!), dist3(finite[1]!, finite[2]!));
      // Far outside the view and already small: this branch's limit points are not seen.
      if (br.depth > 2 && finite.every((p) => dist3(p, centre) > reach + 3 * spread)) continue;
      const depthAlong = Math.max(dot3(sub3(finite[1]!, basis.origin), basis.forward), 1e-6);
      if (spread <= perPixel * depthAlong || br.depth >= set.maxDepth) {
        if (spread > perPixel * depthAlong)
          capped ??= `some words reached ${set.maxDepth} letters before their points came within a pixel: raise "max depth" for a finer limit set`;
        leaves++;
        for (const at of finite) points.push({ at, letter: br.first });
        if (points.length >= MAX_LIMIT_POINTS_3D) {
          capped = `the search stopped at ${MAX_LIMIT_POINTS_3D} points: raise "leaf size"`;
          break;
        }
        continue;
      }
    } else if (br.depth >= set.maxDepth) continue;
    // Rescaling a long product by a real number keeps its action and its entries in range.
    const s = qmSize(br.word);
    const word = s > 1e8 || s < 1e-8 ? qmScale(br.word, 1 / s) : br.word;
    for (let k = 3; k >= 1; k--) {
      const t = mod4(br.last + 2 + k);
      stack.push({ word: qmMul(word, gens[t]!), last: t, first: br.first, depth: br.depth + 1 });
    }
  }
  return { points, words, leaves, ...(capped ? { capped } : {}) };
}
