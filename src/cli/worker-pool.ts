/**
 * A pool of worker threads running one TypeScript job module: each worker takes the next job as
 * soon as it answers the previous one, so `size` jobs run at once until the queue is empty.
 * The job module answers every message (a job) with one message (its result). Used by
 * `npm run render-examples` and `kleinflow render --frames`.
 */
import { Worker } from 'node:worker_threads';

/** Workers start without tsx: register it there first, then load the TypeScript job module. */
const bootstrap = (module: URL) => `import(${JSON.stringify(import.meta.resolve('tsx/esm/api'))})
  .then((tsx) => { tsx.register(); return import(${JSON.stringify(module.href)}); });`;

export function runPool<Job, Result>(
  module: URL,
  jobs: readonly Job[],
  size: number,
  report: (result: Result) => void,
): Promise<void> {
  const queue = [...jobs];
  const worker = () =>
    new Promise<void>((done, fail) => {
      const w = new Worker(bootstrap(module), { eval: true });
      const next = () => {
        const job = queue.shift();
        if (job !== undefined) w.postMessage(job);
        else void w.terminate().then(() => done());
      };
      w.on('message', (r: Result) => {
        report(r);
        next();
      });
      w.on('error', fail);
      next();
    });
  const count = Math.max(1, Math.min(size, jobs.length));
  return Promise.all(Array.from({ length: jobs.length ? count : 0 }, worker)).then(() => undefined);
}
