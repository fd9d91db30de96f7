/**
 * Where a picture lies in the world: a rectangle w × h (world units) centred at c, turned by θ
 * counter-clockwise. Shared by the image colouring and image seeds; glsl/placement.glsl.ts is the
 * twin (same names, same operations in the same order).
 */

/** The rotation packed for both back ends: (cos θ, sin θ). */
export const rotationPair = (theta: number): readonly [number, number] => [Math.cos(theta), Math.sin(theta)];

/**
 * Picture-local coordinates of (x, y): l = R(−θ)(p − c), i.e. lx = cos·dx + sin·dy,
 * ly = −sin·dx + cos·dy; then texture coordinates u = lx/w + ½, v = ½ − ly/h (v = 0 at the top).
 */
export function placeUv(
  cx: number,
  cy: number,
  w: number,
  h: number,
  cos: number,
  sin: number,
  x: number,
  y: number,
): [number, number] {
  const dx = x - cx;
  const dy = y - cy;
  const lx = cos * dx + sin * dy;
  const ly = -sin * dx + cos * dy;
  return [lx / w + 0.5, 0.5 - ly / h];
}
