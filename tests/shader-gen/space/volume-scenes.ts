/**
 * Volume-rendered Scene3d fixtures (docs/math-3d.md "§11 Volume rendering of the nesting depth") for
 * the CPU volume tests, the GLSL checks and GPU = CPU parity: one mirror sphere seen head-on (its
 * optical depth is density × chord), Fig. 11's six mirrors as a cloud, and no mirrors at all.
 */
import type { Scene3d, Volume3d } from '../../../nodes/core/scene-3d.ts';
import { PALETTES } from '../../../nodes/types/colour.ts';
import { FIG11, scene3d, seedSphere } from './scenes-3d.ts';

export const VOLUME: Volume3d = {
  steps: 64,
  density: 0.5,
  growth: 3,
  depthFrom: 1,
  depthTo: 5,
  ...PALETTES.rainbow!,
};

/** One mirror of radius 1 at the origin, the camera on −y at distance 5; every depth is 0 or 1. */
export const ONE_MIRROR: Scene3d = scene3d(
  [{ kind: 'sphere-inversion', sphere: { center: [0, 0, 0], radius: 1 } }],
  [seedSphere([3, 3, 3], 0.2)],
  { camera: { position: [0, -5, 0], target: [0, 0, 0], fovDeg: 40 }, volume: VOLUME },
);

/** Fig. 11's six mirrors as a cloud of nested spheres (Fig. 10), seen from farther away. */
export const NESTED: Scene3d = {
  ...FIG11,
  maxIterations: 20,
  camera: { position: [4.6, -6.1, 3.7], target: [0, 0, 0], fovDeg: 40 },
  volume: VOLUME,
};

/** No mirrors: nothing has depth, the picture is the background. */
export const NO_MIRRORS: Scene3d = { ...ONE_MIRROR, elements: [] };
