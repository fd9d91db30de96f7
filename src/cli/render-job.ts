/**
 * One render job of `npm run render-examples`, run on a worker thread: load the example with the
 * CLI's loader, render it on the CPU, write the PNG. Answers each job with its time or its error.
 */
import { parentPort } from 'node:worker_threads';
import { CliError } from './command.ts';
import { loadScene } from './load-graph.ts';
import { nodeIo } from './node-io.ts';
import { renderScenePng } from './render-png.ts';

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
    const { scene, text } = await loadScene(io, job.input);
    const png = renderScenePng(scene, job.embedGraph ? text : null, {
      width: job.width,
      height: job.height,
      samples: job.samples,
    });
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
