/**
 * "Explain this pixel": the IIS run at one point, step by step — which element applied, where the
 * point went, the accumulated length scale — and why it stopped. Recorded by runIis's observer, so
 * the trace is the interpreter's own loop (docs/math.md "The IIS loop"), never a second copy: its
 * depth, final point and scale are interpret()'s by construction (tests/shader-gen/trace.test.ts).
 */
import type { Scene, SeedSpec } from '../nodes/core/scene.ts';
import type { Circle, Vec2 } from '../nodes/core/values.ts';
import type { IisState } from './elements/element-kind.ts';
import { type IisResult, prepare, runIis } from './interpret.ts';
import { seedAt } from './seeds.ts';

/**
 * Why a run stopped: the point reached the tile (no element holds it: the fundamental domain), it
 * was still inside an element at maxIterations (on or near the limit set), it lay in an orbit seed
 * at the start of a step, or it was outside the clip disk (the loop never ran).
 */
export type StopReason = 'fundamental-domain' | 'limit' | 'seed' | 'clipped';

export interface TraceStep {
  /** Index of the applied element in scene.elements (graph order). */
  readonly element: number;
  /** The node that produced it. */
  readonly nodeId: string;
  /** Depth after the step (a closed-form fold may add more than 1). */
  readonly depth: number;
  /** The point after the step (the point before it is the previous step's, or the start). */
  readonly x: number;
  readonly y: number;
  /** The accumulated length scale after the step (docs/math.md "Length scale"). */
  readonly factor: number;
}

export interface IisTrace extends IisResult {
  readonly start: Vec2;
  readonly steps: readonly TraceStep[];
  readonly stop: StopReason;
  /** Index of the seed the run stopped in (stop 'seed'), else −1. */
  readonly seed: number;
}

export interface TraceOptions {
  /** Orbit seeds that stop the run (docs/math.md "Orbit seeds"); none by default. */
  readonly seeds?: readonly SeedSpec[];
  /** Points outside this disk are not run (the picture's background); none by default. */
  readonly clip?: Circle | null;
}

/** Outside the clip disk: |p − c|² > r² (on the rim counts as inside, as on the GPU). */
export const outsideClip = (clip: Circle | null | undefined, x: number, y: number): boolean =>
  clip != null && (x - clip.c[0]) ** 2 + (y - clip.c[1]) ** 2 > clip.r * clip.r;

export function trace(
  scene: Pick<Scene, 'elements' | 'maxIterations'>,
  p: Vec2,
  options: TraceOptions = {},
): IisTrace {
  const start: Vec2 = [p[0], p[1]];
  const steps: TraceStep[] = [];
  if (outsideClip(options.clip, p[0], p[1])) {
    return { start, steps, stop: 'clipped', seed: -1, depth: 0, final: start, escaped: false, scale: 1 };
  }
  const { elements } = scene;
  const seeds = options.seeds ?? [];
  let seed = -1;
  const st: IisState = { x: p[0], y: p[1], s: 1, depth: 0 };
  const escaped = runIis(prepare(elements), scene.maxIterations, st, (at, applied) => {
    if (applied >= 0) {
      const nodeId = elements[applied].nodeId;
      steps.push({ element: applied, nodeId, depth: at.depth, x: at.x, y: at.y, factor: at.s });
    }
    if (seeds.length === 0) return undefined;
    seed = seedAt(seeds, at.x, at.y);
    return seed >= 0;
  });
  const stop: StopReason = escaped ? 'fundamental-domain' : seed >= 0 ? 'seed' : 'limit';
  return { start, steps, stop, seed, depth: st.depth, final: [st.x, st.y], escaped, scale: st.s };
}

/** What the picture does at p (raster.ts sampleColour): the clip disk and the tile's seeds apply. */
export const tracePicture = (scene: Scene, p: Vec2): IisTrace =>
  trace(scene, p, { seeds: scene.tile.seeds, clip: scene.clip });
