/**
 * "Explain this pixel" for a 3D graph, on the CPU: the camera ray through the pixel is sphere
 * traced by the reference tracer (trace-3d.ts, the picture's own twin) and, where it hits, the IIS
 * of the hit point is run step by step (nodes/geometry/space/iis-3d.ts, with its observer), giving
 * the word of elements that maps the hit point back into the fundamental domain onto a seed
 * (docs/math-3d.md §4). The word is the loop's own record, not a second copy of it.
 */
import type { Element3d, Scene3d } from '../../nodes/core/scene-3d.ts';
import { iis3d } from '../../nodes/geometry/space/iis-3d.ts';
import type { Vec3 } from '../../nodes/geometry/space/vec3.ts';
import { prepareTrace3d } from './plan.ts';
import { tracePixel } from './render-3d.ts';

/**
 * Why the explanation ends: the hit point's run reached the fundamental domain on a seed (`seed`),
 * was still inside an element at maxIterations (`limit`), or the ray hit nothing (`missed`).
 */
export type Stop3d = 'seed' | 'limit' | 'missed';

export interface Trace3dStep {
  /** Index of the applied element in scene.elements (graph order). */
  readonly element: number;
  readonly nodeId: string;
  /** Depth after the step. */
  readonly depth: number;
  /** The point after the step. */
  readonly at: Vec3;
  /** The accumulated conformal factor after the step. */
  readonly factor: number;
}

export interface PixelTrace3d {
  /** The ray: from the camera along `direction`; `t` where it hit (or where the march gave up). */
  readonly origin: Vec3;
  readonly direction: Vec3;
  readonly t: number;
  readonly marchSteps: number;
  /** The hit point (the start of the IIS run); for a miss, where the march stopped. */
  readonly start: Vec3;
  readonly steps: readonly Trace3dStep[];
  readonly depth: number;
  readonly final: Vec3;
  readonly scale: number;
  readonly stop: Stop3d;
  /** Index of the seed hit (stop `seed` or `limit` after a hit), else −1. */
  readonly seed: number;
}

/** The node that made an element (a graph's elements carry it: NodeElement3d), else ''. */
const nodeIdOf = (e: Element3d): string => ('nodeId' in e && typeof e.nodeId === 'string' ? e.nodeId : '');

/**
 * The pixel at image point (px, py) of a width × height picture, py counted from the BOTTOM (as
 * tracePixel and gl_FragCoord), through `scene.camera`.
 */
export function explainPixel3d(
  scene: Scene3d,
  width: number,
  height: number,
  px: number,
  py: number,
): PixelTrace3d {
  const { o, d, hit } = tracePixel(prepareTrace3d(scene), width, height, px, py);
  const start: Vec3 = [o[0] + d[0] * hit.t, o[1] + d[1] * hit.t, o[2] + d[2] * hit.t];
  const ray = { origin: o, direction: d, t: hit.t, marchSteps: hit.steps, start };
  if (!hit.hit) return { ...ray, steps: [], depth: 0, final: start, scale: 1, stop: 'missed', seed: -1 };
  const steps: Trace3dStep[] = [];
  const run = iis3d(scene.elements, start, scene.maxIterations, (element, at, factor, depth) =>
    steps.push({ element, nodeId: nodeIdOf(scene.elements[element]!), depth, at, factor }),
  );
  return {
    ...ray,
    steps,
    depth: run.depth,
    final: run.point,
    scale: run.factor,
    stop: run.escaped ? 'seed' : 'limit',
    seed: hit.seed,
  };
}
