/**
 * The Fig. 6 limit-set search off the main thread (docs/math-3d.md "Quaternion Kleinian groups"):
 * a module worker that takes a scene, its camera and the overlay's size, runs the depth-first
 * search and the dot painter of shader-gen/space/limit-dots-3d.ts (the CLI's and PNG export's
 * code), and sends back the painted RGBA pixels (transferred, not copied) and the search's notes.
 * The search takes up to about a second at full size; on the main thread it froze the editor.
 */
import type { Scene3d } from '../../../nodes/core/scene-3d.ts';
import { limitDots3d, paintLimitDots3d } from '../../../shader-gen/space/limit-dots-3d.ts';

export interface LimitSetJob {
  readonly id: number;
  readonly scene: Scene3d;
  readonly width: number;
  readonly height: number;
}

export interface LimitSetResult {
  readonly id: number;
  readonly width: number;
  readonly height: number;
  readonly pixels: Uint8ClampedArray<ArrayBuffer>;
  readonly notes: readonly string[];
}

/** Searches and paints one job (also the fallback where no worker can start). */
export function paintLimitSetJob({ id, scene, width, height }: LimitSetJob): LimitSetResult {
  const { dots, notes } = limitDots3d(scene, width, height);
  const pixels = new Uint8ClampedArray(width * height * 4);
  paintLimitDots3d(scene, dots, width, height, pixels);
  return { id, width, height, pixels, notes: notes.map((n) => n.text) };
}

// In a worker (not when imported by the overlay for the fallback): answer each job.
const scope = globalThis as unknown as {
  WorkerGlobalScope?: unknown;
  onmessage: ((e: MessageEvent<LimitSetJob>) => void) | null;
  postMessage(message: LimitSetResult, transfer: Transferable[]): void;
};
if (typeof scope.WorkerGlobalScope !== 'undefined') {
  scope.onmessage = (e) => {
    const result = paintLimitSetJob(e.data);
    scope.postMessage(result, [result.pixels.buffer]);
  };
}
