/**
 * The pinhole camera of Scene3d (z up), CPU and GLSL twins. forward f = normalize(target − position),
 * right = normalize(f × up) with up = z (or y when f is almost vertical), up' = right × f. Pixel
 * (px + jx, py + jy), py counted from the BOTTOM row like gl_FragCoord, looks along
 *   normalize(f + u·right + v·up'),  u = (px + jx − W/2)·a,  v = (py + jy − H/2)·a,
 *   a = 2·tan(fov/2)/H  (the angle one pixel subtends at the centre, used for hit tolerances).
 */
import type { Camera3d } from '../../nodes/core/scene-3d.ts';
import { cross3, normalize3, sub3, type Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { glslFunction } from '../glsl/snippet.ts';

/** |f.z| above this: the view is almost vertical and y serves as the up reference. */
export const VERTICAL_VIEW = 0.999;

export interface CameraBasis {
  readonly origin: Vec3;
  readonly forward: Vec3;
  readonly right: Vec3;
  readonly up: Vec3;
  /** tan(fov/2). */
  readonly tanHalf: number;
}

export function cameraBasis(c: Camera3d): CameraBasis {
  const forward = normalize3(sub3(c.target, c.position));
  const ref: Vec3 = Math.abs(forward[2]) > VERTICAL_VIEW ? [0, 1, 0] : [0, 0, 1];
  const right = normalize3(cross3(forward, ref));
  return {
    origin: c.position,
    forward,
    right,
    up: cross3(right, forward),
    tanHalf: Math.tan((c.fovDeg * Math.PI) / 360),
  };
}

/** Angle per pixel a = 2 tan(fov/2)/H. */
export const pixelAngle = (b: CameraBasis, height: number): number => (2 * b.tanHalf) / height;

/** The unit ray direction through image point (px, py) (fractional, from the bottom-left corner). */
export function rayDirection(b: CameraBasis, width: number, height: number, px: number, py: number): Vec3 {
  const a = pixelAngle(b, height);
  const u = (px - width / 2) * a;
  const v = (py - height / 2) * a;
  return normalize3([
    b.forward[0] + u * b.right[0] + v * b.up[0],
    b.forward[1] + u * b.right[1] + v * b.up[1],
    b.forward[2] + u * b.right[2] + v * b.up[2],
  ]);
}

/** GLSL `vec3 cameraRay(vec3 position, vec3 target, float fovDeg, vec2 size, vec2 at)`. */
export const cameraRayGlsl = glslFunction(
  'cameraRay',
  `
vec3 cameraRay(vec3 position, vec3 target, float fovDeg, vec2 size, vec2 at) {
  vec3 f = normalize(target - position);
  vec3 upRef = abs(f.z) > ${VERTICAL_VIEW} ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
  vec3 right = normalize(cross(f, upRef));
  vec3 up = cross(right, f);
  float a = 2.0 * tan(radians(fovDeg) * 0.5) / size.y;
  vec2 uv = (at - size * 0.5) * a;
  return normalize(f + uv.x * right + uv.y * up);
}`,
);
