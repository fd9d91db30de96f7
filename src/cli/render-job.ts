/**
 * One render job of `npm run render-examples`: load the example with the CLI's loader, render it
 * on the CPU, write the PNG. A plane example runs whole on a worker thread of the examples' pool
 * (runRenderJob); a space example is split over every core itself (render3dJob, on the main
 * thread, one at a time), since one sphere-traced picture outlasts all the plane ones together.
 * Answers each job with its time or its error.
 */
import { parentPort } from 'node:worker_threads';
import { spaceViewTarget } from '../../nodes/graph/space-view.ts';
import { CliError } from './command.ts';
import { loadAnyScene, loadScene } from './load-graph.ts';
import { nodeIo } from './node-io.ts';
import { renderScene3dPngOnPool, renderScenePng } from './render-png.ts';

export interface RenderJob {
  readonly name: string;
  readonly input: string;
  readonly output: string;
  readonly width: number;
  readonly height: number;
  /** Samples per pixel (the render node's own when absent). */
  readonly samples?: number;
  /** Whether the graph travels inside the PNG (false for gallery thumbnails). */
  readonly embedGraph: boolean;
}

export interface RenderJobResult {
  readonly name: string;
  readonly ms: number;
  readonly error?: string;
}

/** Runs `render` (which returns the PNG) and writes it, timed; a failure becomes the result's error. */
async function timedJob(job: RenderJob, render: () => Promise<Uint8Array>): Promise<RenderJobResult> {
  const started = performance.now();
  try {
    await nodeIo().writeFile(job.output, await render());
    return { name: job.name, ms: performance.now() - started };
  } catch (e) {
    const error = e instanceof CliError || e instanceof Error ? e.message : String(e);
    return { name: job.name, ms: performance.now() - started, error };
  }
}

export function runRenderJob(job: RenderJob): Promise<RenderJobResult> {
  return timedJob(job, async () => {
    const { scene, text } = await loadScene(nodeIo(), job.input);
    const request = { width: job.width, height: job.height, samples: job.samples };
    return renderScenePng(scene, job.embedGraph ? text : null, request);
  });
}

/** A 3D example on `threads` worker threads (render-3d-pool.ts). */
export function render3dJob(job: RenderJob, threads: number): Promise<RenderJobResult> {
  return timedJob(job, async () => {
    const { picture, text, doc } = await loadAnyScene(nodeIo(), job.input);
    if (picture.kind !== '3d') throw new CliError(`"${job.input}" is not a 3D graph`);
    const { width, height } = job;
    const samples = job.samples ?? picture.scene3d.samples;
    const request = { width, height, samples, threads };
    const space = doc ? spaceViewTarget(doc) : null;
    return renderScene3dPngOnPool(picture.scene3d, job.embedGraph ? text : null, request, space);
  });
}

parentPort?.on('message', (job: RenderJob) => {
  void runRenderJob(job).then((r) => parentPort?.postMessage(r));
});
