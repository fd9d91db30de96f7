/**
 * A worker thread of a 3D still (src/cli/render-3d-pool.ts): renders bands of rows of one image
 * with the CPU sphere tracer and answers each with its RGBA bytes. The scene and image settings
 * come once, as workerData; the trace plan is built from them on the first band and kept, so a
 * thread pays for it once, not once per band.
 */
import { parentPort, workerData } from 'node:worker_threads';
import type { Scene3d } from '../../nodes/core/scene-3d.ts';
import { type Render3dFrame, render3dFrame, renderRows3d } from '../../shader-gen/space/render-3d.ts';

/** What every band of one image shares. */
export interface Band3dSetup {
  readonly scene: Scene3d;
  readonly width: number;
  readonly height: number;
  readonly samples: number;
}

/** Rows start … end − 1, row 0 at the top. */
export interface Band3d {
  readonly start: number;
  readonly end: number;
}

export type Band3dResult =
  | (Band3d & { readonly data: Uint8ClampedArray })
  | (Band3d & { readonly error: string });

/** The plan of the setup this thread last rendered (a worker only ever has one). */
let built: { setup: Band3dSetup; frame: Render3dFrame } | undefined;

export function runBand3d(setup: Band3dSetup, band: Band3d): Band3dResult {
  try {
    if (built?.setup !== setup) {
      const { scene, width, height, samples } = setup;
      built = { setup, frame: render3dFrame(scene, width, height, { samples }) };
    }
    const data = new Uint8ClampedArray(4 * setup.width * (band.end - band.start));
    renderRows3d(built.frame, band.start, band.end, data);
    return { ...band, data };
  } catch (e) {
    // Answered, not thrown: the main thread names the band and stops the others cleanly.
    return { ...band, error: e instanceof Error ? e.message : String(e) };
  }
}

parentPort?.on('message', (band: Band3d) => {
  const result = runBand3d(workerData as Band3dSetup, band);
  parentPort?.postMessage(result, 'data' in result ? [result.data.buffer as ArrayBuffer] : []);
});
