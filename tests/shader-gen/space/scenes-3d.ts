/**
 * Hand-built Scene3d fixtures for the tracer tests, the GLSL checks, parity and the bench (until
 * the 3D nodes' examples exist): Fig. 11 (six inversion spheres at ±a·e_k around one seed
 * sphere), a lone seed sphere, and mixed scenes that take the fallback bound.
 */
import { readFileSync } from 'node:fs';
import {
  DEFAULT_CAMERA_3D,
  DEFAULT_LIGHTING_3D,
  type Element3d,
  type Scene3d,
  type Seed3d,
} from '../../../nodes/core/scene-3d.ts';
import { compoundParabolic3d } from '../../../nodes/geometry/space/compound-parabolic-3d.ts';
import { mobius3d } from '../../../nodes/geometry/space/mobius-3d.ts';
import type { Vec3 } from '../../../nodes/geometry/space/vec3.ts';
import { evaluateGraph } from '../../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../../nodes/graph/load.ts';
import { registry } from '../../../nodes/types/index.ts';
import { EXAMPLES_3D_DIR, exampleNames, examplePath } from '../../../src/cli/examples.ts';

export function scene3d(
  elements: readonly Element3d[],
  seeds: readonly Seed3d[],
  extra: Partial<Scene3d> = {},
): Scene3d {
  return {
    kind: '3d',
    elements,
    seeds,
    camera: DEFAULT_CAMERA_3D,
    maxIterations: 30,
    marchSteps: 200,
    deScale: 1,
    lighting: DEFAULT_LIGHTING_3D,
    coloring: { mode: 'depth-wheel', step: 0.12 },
    background: [0.06, 0.07, 0.1],
    samples: 1,
    renderNodeId: 'render',
    overlays: [],
    handles: [],
    ...extra,
  };
}

export const AXES: readonly Vec3[] = [
  [1, 0, 0],
  [-1, 0, 0],
  [0, 1, 0],
  [0, -1, 0],
  [0, 0, 1],
  [0, 0, -1],
];

/** Six inversion spheres of radius r at ±a·e_k. */
export const sixSpheres = (a = 2, r = 1.25): Element3d[] =>
  AXES.map((e) => ({
    kind: 'sphere-inversion' as const,
    sphere: { center: [e[0] * a, e[1] * a, e[2] * a] as Vec3, radius: r },
  }));

export const seedSphere = (
  center: Vec3,
  radius: number,
  color: Vec3 = [0.9, 0.35, 0.2],
  nodeId = 'seed',
): Seed3d => ({
  kind: 'sphere',
  nodeId,
  sphere: { center, radius },
  color,
});

/** Fig. 11: six inversion spheres and one seed sphere at the origin. */
export const FIG11 = scene3d(sixSpheres(), [seedSphere([0, 0, 0], 0.7)], {
  camera: { position: [3.1, -4.1, 2.5], target: [0, 0, 0], fovDeg: 40 },
});

/** A lone seed sphere seen head-on along −y. */
export const LONE_SPHERE = scene3d([], [seedSphere([0, 0, 0], 1)], {
  camera: { position: [0, -5, 0], target: [0, 0, 0], fovDeg: 40 },
});

const mob = mobius3d({ center: [-1.4, 0, 0], radius: 1 }, { center: [1.4, 0, 0], radius: 1 });
const par = compoundParabolic3d([0, 0, -1.5], [0, 0, 1], 1.5, 0.4);
if (!mob.ok || !par.ok) throw new Error('fixture generators');

/** A hyperbolic two-sphere generator and a seed box: the fallback bound. */
export const MOBIUS_BOX = scene3d(
  [{ kind: 'mobius-3d', g: mob.value }],
  [{ kind: 'box', nodeId: 'box', center: [0, 0, 0], halfSize: [0.22, 0.22, 0.22], color: [0.3, 0.6, 0.9] }],
  { camera: { position: [0.4, -3.2, 1.1], target: [-0.15, 0, 0], fovDeg: 40 } },
);

/** Plane mirrors and a compound parabolic: an unbounded orbit. */
export const PLANES = scene3d(
  [
    { kind: 'plane-reflection', plane: { point: [-1.5, 0, 0], normal: [1, 0, 0] } },
    { kind: 'plane-reflection', plane: { point: [1.5, 0, 0], normal: [-1, 0, 0] } },
    { kind: 'compound-parabolic-3d', g: par.value },
  ],
  [seedSphere([0, 0, 0], 0.6, [0.4, 0.8, 0.4])],
  {
    camera: { position: [1, -9, 3], target: [0, 0, 0], fovDeg: 50 },
    coloring: {
      mode: 'cosine',
      a: [0.5, 0.5, 0.5],
      b: [0.5, 0.5, 0.5],
      c: [1, 1, 1],
      d: [0, 0.33, 0.67],
      step: 0.15,
    },
  },
);

/**
 * The pseudo-Kleinian proper (docs/math-3d.md §10): a box fold and an inversion sphere that crosses
 * the box's faces (not a discrete group), a seed ball in a corner of box minus ball.
 */
export const PSEUDO_KLEINIAN = scene3d(
  [
    { kind: 'box-fold', box: { center: [0, 0, 0], halfSize: [1, 1, 1] } },
    { kind: 'sphere-inversion', sphere: { center: [0, 0, 0], radius: 1.2 } },
  ],
  [seedSphere([0.85, 0.85, 0.85], 0.12, [0.9, 0.75, 0.4])],
  { camera: { position: [1, -1, 0.9], target: [4, 2, -0.5], fovDeg: 60 }, maxIterations: 24 },
);

/**
 * Fig. 11 with its seed a mirror (docs/math-3d.md "Mirror material") among four matte balls outside
 * the inversion spheres, under the sky, two reflections.
 */
export const MIRROR_FIG11 = scene3d(
  sixSpheres(),
  [
    { ...seedSphere([0, 0, 0], 0.7, [0.95, 0.95, 1]), reflectivity: 0.85 },
    seedSphere([4.2, 0, 0.6], 0.6, [0.9, 0.3, 0.3], 'ball1'),
    seedSphere([0, 4.2, -0.5], 0.6, [0.2, 0.7, 0.4], 'ball2'),
    seedSphere([-4.2, 0, 0.4], 0.6, [0.3, 0.4, 0.9], 'ball3'),
    seedSphere([0, -4.2, -0.3], 0.6, [0.9, 0.8, 0.2], 'ball4'),
  ],
  {
    camera: { position: [3.1, -4.1, 1.2], target: [0, 0, 0], fovDeg: 50 },
    environment: { mode: 'sky', horizon: [0.85, 0.9, 0.95], ground: [0.5, 0.45, 0.4] },
    reflections: 2,
  },
);

/** The scene3d of every 3D example. */
export function exampleScenes3d(): Record<string, Scene3d> {
  const out: Record<string, Scene3d> = {};
  for (const name of exampleNames(EXAMPLES_3D_DIR)) {
    const loaded = parseDocumentText(readFileSync(examplePath(name, EXAMPLES_3D_DIR), 'utf8'), registry);
    if (!loaded.ok) throw new Error(`${name} does not load`);
    const scene = evaluateGraph(loaded.doc, registry).scene3d;
    if (!scene) throw new Error(`${name} has no 3D scene`);
    out[name] = scene;
  }
  return out;
}
