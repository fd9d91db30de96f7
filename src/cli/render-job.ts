/**
 * One render job of `npm run render-examples`, run on a worker thread: load the example with the
 * CLI's loader, render it on the CPU (the IIS raster, or the sphere tracer for a 3D graph), write
 * the PNG. Answers each job with its time or its error.
 */
import { parentPort } from 'node:worker_threads';
import { CliError } from './command.ts';
import { loadAnyScene } from './load-graph.ts';
import { nodeIo } from './node-io.ts';
import { renderScene3dPng, renderScenePng } from './render-png.ts';

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

export async function runRenderJob(job: RenderJob): Promise<RenderJobResult> {
  const started = performance.now();
  const io = nodeIo();
  try {
    const { picture, text } = await loadAnyScene(io, job.input);
    const request = { width: job.width, height: job.height, samples: job.samples };
    const graph = job.embedGraph ? text : null;
    const png =
      picture.kind === '3d'
        ? renderScene3dPng(picture.scene3d, graph, request)
        : renderScenePng(picture.scene, graph, request);
    await io.writeFile(job.output, png);
    return { name: job.name, ms: performance.now() - started };
  } catch (e) {
    const error = e instanceof CliError || e instanceof Error ? e.message : String(e);
    return { name: job.name, ms: performance.now() - started, error };
  }
}

parentPort?.on('message', (job: RenderJob) => {
  void runRenderJob(job).then((r) => parentPort?.postMessage(r));
});
