/** Comparing 3D cameras (nodes/core/scene-3d.ts Camera3d), for the view state's no-op checks. */
import type { Camera3d } from './scene-3d.ts';

export const sameCamera3d = (a: Camera3d, b: Camera3d): boolean =>
  a.fovDeg === b.fovDeg &&
  a.position.every((v, i) => v === b.position[i]) &&
  a.target.every((v, i) => v === b.target[i]);
