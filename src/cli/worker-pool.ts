/**
 * A pool of worker threads running one TypeScript job module: each worker takes the next job as
 * soon as it answers the previous one, so `size` jobs run at once until the queue is empty.
 * The job module answers every message (a job) with one message (its result). Used by
 * `npm run render-examples`, `kleinflow render --frames` and the bands of a 3D still.
 */
import { Worker } from 'node:worker_threads';

/** Workers start without tsx: register it there first, then load the TypeScript job module. */
const bootstrap = (module: URL) => `import(${JSON.stringify(import.meta.resolve('tsx/esm/api'))})
  .then((tsx) => { tsx.register(); return import(${JSON.stringify(module.href)}); });`;

export interface PoolOptions {
  /**
   * Handed to every worker once, at its start (`workerData`): what all its jobs share (a 3D
   * scene), so it is copied once per thread, not once per job.
   */
  readonly workerData?: unknown;
}

/**
 * Runs every job; `report` gets each result as it comes and may return false to stop: no more
 * jobs are handed out, the ones under way finish. A worker that fails (throws outside a job,
 * exits) rejects the run with its error, and every other worker is stopped at once, so a
 * command fails promptly instead of rendering on with no one to take the result.
 */
export function runPool<Job, Result>(
  module: URL,
  jobs: readonly Job[],
  size: number,
  report: (result: Result) => unknown,
  options: PoolOptions = {},
): Promise<void> {
  const queue = [...jobs];
  const workers = new Set<Worker>();
  const stopAll = () => {
    queue.length = 0;
    for (const w of workers) void w.terminate();
  };
  const worker = () =>
    new Promise<void>((done, fail) => {
      const w = new Worker(bootstrap(module), { eval: true, workerData: options.workerData });
      workers.add(w);
      let finished = false;
      const next = () => {
        const job = queue.shift();
        if (job !== undefined) {
          w.postMessage(job);
          return;
        }
        finished = true;
        workers.delete(w);
        void w.terminate().then(() => done());
      };
      w.on('message', (r: Result) => {
        if (report(r) === false) queue.length = 0;
        next();
      });
      w.on('error', (e) => {
        finished = true;
        stopAll();
        fail(e);
      });
      // A worker that ends by itself (process.exit in a job, out of memory) never answers again.
      w.on('exit', (code) => {
        if (finished) return;
        finished = true;
        stopAll();
        fail(new Error(`a worker thread stopped unexpectedly (exit code ${code})`));
      });
      next();
    });
  const count = Math.max(1, Math.min(size, jobs.length));
  return Promise.all(Array.from({ length: jobs.length ? count : 0 }, worker)).then(() => undefined);
}
