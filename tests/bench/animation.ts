/**
 * `kleinflow render --frames` throughput: the animated example's frames (PNG, encoded on the
 * workers) on one worker thread, then on every core; prints frames/s and the speed-up. Worker
 * start-up (tsx in each thread) is included, as a user pays it too.
 */
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { availableParallelism, tmpdir } from 'node:os';
import { join } from 'node:path';
import type { CliIo } from '../../src/cli/command.ts';
import { examplePath } from '../../src/cli/examples.ts';
import { renderAnimation } from '../../src/cli/render-animation.ts';

const FRAMES = 48;
const SIZE = 200;
const SAMPLES = 2;

/** Output goes nowhere: the bench measures rendering and encoding, not the disk. */
const quietIo: CliIo = {
  stdout: { write: () => undefined },
  stderr: { write: () => undefined },
  open: async (path) => {
    throw new Error(`the animation bench reads no files (asked for ${path})`);
  },
  writeFile: async () => undefined,
};

async function framesPerSecond(text: string, threads: number, out: string): Promise<number> {
  const started = performance.now();
  await renderAnimation(quietIo, {
    text,
    frames: FRAMES,
    fps: 24,
    range: { start: 0, end: FRAMES },
    out,
    width: SIZE,
    height: SIZE,
    samples: SAMPLES,
    threads,
  });
  return FRAMES / ((performance.now() - started) / 1000);
}

export async function run(): Promise<void> {
  const text = readFileSync(examplePath('animated-breathing-loxodromic'), 'utf8');
  const out = mkdtempSync(join(tmpdir(), 'kleinflow-bench-'));
  const cores = availableParallelism();
  try {
    const one = await framesPerSecond(text, 1, out);
    const all = await framesPerSecond(text, cores, out);
    console.log(`\nAnimation frames (${FRAMES} frames ${SIZE}², ${SAMPLES} samples/px, PNG)`);
    console.log(`  1 thread:   ${one.toFixed(2)} frames/s`);
    console.log(
      `  ${String(cores).padEnd(2)} threads: ${all.toFixed(2)} frames/s  (speed-up ×${(all / one).toFixed(2)})`,
    );
  } finally {
    rmSync(out, { recursive: true, force: true });
  }
}
