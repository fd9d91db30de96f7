/**
 * `npm run bench`: prints throughput figures, never fails on a time. Runs each bench module in
 * BENCHES in order; a module that is not there (e.g. the GPU bench on a checkout without it) is
 * skipped with a note. A module exports `run(): Promise<void>` and prints its own table.
 */
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

/** Bench modules, relative to this file. Add a line to add a bench. */
const BENCHES = [
  './cpu.ts',
  './gpu.ts',
  './shader-ratio.ts',
  './colour-ratio.ts',
  './scale.ts',
  './source.ts',
  './editor.ts',
  './animation.ts',
  './trace3d.ts',
  './first-draw3d.ts',
  './volume3d.ts',
  './cpu3d.ts',
  './cpu-volume.ts',
  './mesh.ts',
] as const;

async function main(): Promise<void> {
  for (const rel of BENCHES) {
    const url = new URL(rel, import.meta.url);
    if (!existsSync(fileURLToPath(url))) {
      console.log(`\n(${rel} not present: skipped)`);
      continue;
    }
    const mod = (await import(url.href)) as { run?: () => Promise<void> };
    if (typeof mod.run !== 'function') {
      console.log(`\n(${rel} exports no run(): skipped)`);
      continue;
    }
    await mod.run();
  }
}

main().catch((e) => {
  console.error(`bench: ${e instanceof Error ? e.stack : String(e)}`);
  process.exitCode = 1;
});
