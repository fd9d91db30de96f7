/**
 * Shared arithmetic of the strip kinds (translation, parallel mirrors, glide reflection): the
 * signed height h = (p − q)·n across the strip and the strip index k = ⌊h/D⌋ (k = 0 is the
 * half-open tile 0 ≤ h < D, docs/math.md "Closed-form elements"), on the CPU and in GLSL. A strip
 * packs into two vec4s: d0 = (q.x, q.y, n.x, n.y), d1 = (period D, 0, 0, 0).
 */
import type { StripData } from '../../nodes/core/scene.ts';
import { glslFunction } from '../glsl/snippet.ts';

/** h = (p − q)·n: the height of (x, y) above the strip's first edge. */
export const stripHeight = (e: StripData, x: number, y: number): number =>
  (x - e.q[0]) * e.n[0] + (y - e.q[1]) * e.n[1];

/** k = ⌊h/D⌋: how many periods (x, y) lies away from the tile (negative below it). */
export const stripIndex = (e: StripData, x: number, y: number): number =>
  Math.floor(stripHeight(e, x, y) / e.period);

/** Distance to the nearer strip edge h = 0 or h = D. */
export function stripBoundaryDistance(e: StripData, x: number, y: number): number {
  const h = stripHeight(e, x, y);
  return Math.min(Math.abs(h), Math.abs(h - e.period));
}

export const packStrip = (e: StripData): number[] => [e.q[0], e.q[1], e.n[0], e.n[1], e.period, 0, 0, 0];

/** The arguments every strip kind's functions take after p. */
export const STRIP_ARGS = 'vec4 d0, vec4 d1';

/** h = (p − q)·n. */
export const stripHeightGlsl = glslFunction(
  'stripHeight',
  `
float stripHeight(vec4 d0, vec2 p) {
  return (p.x - d0.x) * d0.z + (p.y - d0.y) * d0.w;
}`,
);

/** k = ⌊h/D⌋ (a whole number held in a float, as the CPU's number). */
export const stripIndexGlsl = glslFunction(
  'stripIndex',
  `
float stripIndex(vec4 d0, vec4 d1, vec2 p) {
  return floor(stripHeight(d0, p) / d1.x);
}`,
  [stripHeightGlsl],
);

/** min(|h|, |h − D|). */
export const stripBoundaryDistanceGlsl = glslFunction(
  'stripBoundaryDistance',
  `
float stripBoundaryDistance(vec4 d0, vec4 d1, vec2 p) {
  float h = stripHeight(d0, p);
  return min(abs(h), abs(h - d1.x));
}`,
  [stripHeightGlsl],
);

/**
 * A fold by k periods counts |k| steps of depth (the loop adds 1, the step foldCount(k) − 1). A
 * point farther than 10⁹ periods away (only reachable from absurd views) counts 10⁹, which keeps
 * the int finite and still reaches any maxIterations. At least 1 (a fold only happens for k ≠ 0;
 * NaN, whose int() is undefined, counts 1), so the step never takes depth back.
 */
export const foldCountGlsl = glslFunction(
  'foldCount',
  `
int foldCount(float k) {
  return max(int(min(abs(k), 1.0e9)), 1);
}`,
);

/** `inside` of every strip kind: k ≠ 0. */
export const stripInside = (kind: string) =>
  glslFunction(
    `${kind}Inside`,
    `
bool ${kind}Inside(vec2 p, ${STRIP_ARGS}) {
  return stripIndex(d0, d1, p) != 0.0;
}`,
    [stripIndexGlsl],
  );

/** `boundaryDistance` of every strip kind: distance to the nearer strip edge. */
export const stripDistance = (kind: string) =>
  glslFunction(
    `${kind}BoundaryDistance`,
    `
float ${kind}BoundaryDistance(vec2 p, ${STRIP_ARGS}) {
  return stripBoundaryDistance(d0, d1, p);
}`,
    [stripBoundaryDistanceGlsl],
  );
