/**
 * Runs a `kleinflow` command in this process: main() with the real file system (src/cli/node-io.ts)
 * and what it writes captured — the executable less its process. A new Node process costs about a
 * second of CPU (start-up and tsx loading the TypeScript sources), so the many cheap cases (usage
 * errors, `check`, refused inputs) run here; run-cli.ts runs the real executable for the rest
 * (pictures, worker threads, exit statuses through the process).
 */
import { main } from '../../src/cli/main.ts';
import { nodeIo } from '../../src/cli/node-io.ts';
import type { CliRun } from './run-cli.ts';

export async function runMain(args: readonly string[]): Promise<CliRun> {
  let stdout = '';
  let stderr = '';
  const status = await main([...args], {
    ...nodeIo(),
    stdout: {
      write: (t) => {
        stdout += t;
      },
    },
    stderr: {
      write: (t) => {
        stderr += t;
      },
    },
  });
  return { status, stdout, stderr };
}
