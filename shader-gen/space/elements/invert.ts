/**
 * Sphere inversion of the walk state, shared by every kind that inverts (CPU and GLSL twins):
 *   d = x − c, |d|² clamped below by TINY (the centre itself has no finite image: it goes very far
 *   instead of to ∞, like the 2D centre guard), k = r²/|d|², x ← c + k·d, s ← s·k;
 * the record pushed first is (r², |x' − c| = r²/|d|). docs/math-3d.md §1.
 */
import { floatLiteral } from '../../glsl/literal.ts';
import { glslFunction } from '../../glsl/snippet.ts';
import type { PushInversion, Walk3dState } from './element-3d-kind.ts';

/** Smallest |d|² used (a normal float32, so the GPU computes the same). */
export const TINY_D2 = 1e-30;

export function invertWalk(
  st: Walk3dState,
  cx: number,
  cy: number,
  cz: number,
  r2: number,
  push: PushInversion,
): void {
  const dx = st.x - cx;
  const dy = st.y - cy;
  const dz = st.z - cz;
  const d2 = Math.max(dx * dx + dy * dy + dz * dz, TINY_D2);
  const k = r2 / d2;
  push?.(r2, r2 / Math.sqrt(d2));
  st.x = cx + dx * k;
  st.y = cy + dy * k;
  st.z = cz + dz * k;
  st.s *= k;
}

/** Squared distance from (x, y, z) to (cx, cy, cz). */
export const dist2 = (x: number, y: number, z: number, cx: number, cy: number, cz: number): number =>
  (x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2;

/** GLSL: the inversion factor k = r²/max(|p − c|², TINY) and |p' − c| = r²/|p − c|, as vec2(k, far). */
export const inversionFactorGlsl = glslFunction(
  'inversionFactor',
  `
vec2 inversionFactor(vec3 p, vec3 c, float r2) {
  vec3 d = p - c;
  float d2 = max(dot(d, d), ${floatLiteral(TINY_D2)});
  return vec2(r2 / d2, r2 * inversesqrt(d2));
}`,
);

/**
 * GLSL statements inverting p in the sphere (c, r²) given as expressions, recording first, indented
 * one level (they sit inside the block's `if`). `kf` names a fresh local.
 */
export function invertGlsl(
  c: string,
  r2: string,
  kf: string,
  push: (r2: string, far: string) => string,
): string {
  const rec = push(r2, `${kf}.y`);
  return [
    `vec2 ${kf} = inversionFactor(p, ${c}, ${r2});`,
    ...(rec ? [rec] : []),
    `p = ${c} + (p - ${c}) * ${kf}.x;`,
    `s *= ${kf}.x;`,
  ]
    .join('\n')
    .split('\n')
    .map((line) => `  ${line}`)
    .join('\n');
}
