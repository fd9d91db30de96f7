/** The worker pool stops on request, and a worker that fails fails the run at once (no hang). */
import { describe, expect, it } from 'vitest';
import { runPool } from '../../../src/cli/worker-pool.ts';

const FAULTY = new URL('./support/faulty-job.ts', import.meta.url);

describe('runPool', () => {
  it('hands out no more jobs once report says false', async () => {
    const seen: string[] = [];
    await runPool<string, string>(FAULTY, ['a', 'b', 'c', 'd'], 1, (r) => {
      seen.push(r);
      return false;
    });
    expect(seen).toEqual(['a']);
  });

  it('rejects with the reason when a worker thread ends by itself', async () => {
    const run = runPool<string, string>(FAULTY, ['a', 'exit', 'b', 'c', 'd'], 2, () => true);
    await expect(run).rejects.toThrow('a worker thread stopped unexpectedly (exit code 3)');
  });

  it('rejects with the error a worker throws outside a job', async () => {
    await expect(runPool<string, string>(FAULTY, ['throw', 'a'], 2, () => true)).rejects.toThrow(
      'the job module broke',
    );
  });
});
