import { fileURLToPath } from 'node:url';

/**
 * `npx tsx tests/bench/<module>.ts [N]`: when `moduleUrl` (the module's import.meta.url) is the
 * script being run, calls `run` with the first argument if it is an integer ≥ `min`, else with
 * `fallback`; a failure is printed and sets the exit code.
 */
export function runWhenMain(
  moduleUrl: string,
  run: (n: number) => Promise<void>,
  fallback = 0,
  min = 1,
): void {
  if (!process.argv[1] || fileURLToPath(moduleUrl) !== process.argv[1]) return;
  const n = Number(process.argv[2] ?? fallback);
  run(Number.isInteger(n) && n >= min ? n : fallback).catch((e) => {
    console.error(e);
    process.exitCode = 1;
  });
}
