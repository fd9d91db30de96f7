/**
 * Sphere inversion of the walk state, shared by every kind that inverts (CPU and GLSL twins):
 *   d = x − c, |d|² clamped below by TINY (the centre itself has no finite image: it goes very far
 *   instead of to ∞, like the 2D centre guard), k = r²/|d|², x ← c + k·d, s ← s·k;
 * a tracked pole moves by the same inversion (docs/math-3d.md §1, §8).
 */
import { floatLiteral } from '../../glsl/literal.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import type { Pole3d, Walk3dState } from './element-3d-kind.ts';

/** Smallest |d|² used (a normal float32, so the GPU computes the same). */
export const TINY_D2 = 1e-30;

/** Inverts a point in (c, r²), |d|² clamped below by TINY. Returns the factor k. */
export function invertPoint(pt: Pole3d, cx: number, cy: number, cz: number, r2: number): number {
  const dx = pt.x - cx;
  const dy = pt.y - cy;
  const dz = pt.z - cz;
  const k = r2 / Math.max(dx * dx + dy * dy + dz * dz, TINY_D2);
  pt.x = cx + dx * k;
  pt.y = cy + dy * k;
  pt.z = cz + dz * k;
  return k;
}

export function invertWalk(st: Walk3dState, cx: number, cy: number, cz: number, r2: number): void {
  st.s *= invertPoint(st, cx, cy, cz, r2);
  if (st.pole) invertPoint(st.pole, cx, cy, cz, r2);
}
/** Squared distance from (x, y, z) to (cx, cy, cz). */
export const dist2 = (x: number, y: number, z: number, cx: number, cy: number, cz: number): number =>
  (x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2;

/** GLSL: the inversion factor k = r²/max(|p − c|², TINY). */
export const inversionFactorGlsl = glslFunction(
  'inversionFactor',
  `
float inversionFactor(vec3 p, vec3 c, float r2) {
  vec3 d = p - c;
  return r2 / max(dot(d, d), ${floatLiteral(TINY_D2)});
}`,
);

/**
 * GLSL statements inverting p (and, with `pole`, the tracked pole) in the sphere (c, r²) given as
 * expressions, indented one level (they sit inside the block's `if`). `kf` names a fresh local.
 */
export function invertGlsl(c: string, r2: string, kf: string, pole: boolean): string {
  return [
    `float ${kf} = inversionFactor(p, ${c}, ${r2});`,
    `p = ${c} + (p - ${c}) * ${kf};`,
    `s *= ${kf};`,
    ...(pole ? [`pole = ${c} + (pole - ${c}) * inversionFactor(pole, ${c}, ${r2});`] : []),
  ]
    .map((line) => `  ${line}`)
    .join('\n');
}
