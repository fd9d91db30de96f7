/** GLSL twin of shader-gen/placement.ts (same name, same operations in the same order). */
import { glslFunction } from './snippet.ts';

/**
 * `vec2 placeUv(vec4 rect, vec2 rot, vec2 p)`: rect = (c.x, c.y, w, h), rot = (cos θ, sin θ);
 * l = R(−θ)(p − c), uv = (lx/w + ½, ½ − ly/h).
 */
export const placeUvGlsl = glslFunction(
  'placeUv',
  `
vec2 placeUv(vec4 rect, vec2 rot, vec2 p) {
  float dx = p.x - rect.x;
  float dy = p.y - rect.y;
  float lx = rot.x * dx + rot.y * dy;
  float ly = -rot.y * dx + rot.x * dy;
  return vec2(lx / rect.z + 0.5, 0.5 - ly / rect.w);
}`,
);
