/**
 * A job module for the worker-pool tests: answers a job with itself, except "exit" (the thread
 * ends, as on process.exit or running out of memory) and "throw" (an error outside any answer).
 */
import { parentPort } from 'node:worker_threads';

parentPort?.on('message', (job: string) => {
  if (job === 'exit') process.exit(3);
  if (job === 'throw') throw new Error('the job module broke');
  parentPort?.postMessage(job);
});
