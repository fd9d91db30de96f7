/**
 * `npm run render-examples [-- NAME...] [--size WxH] [--thumbnails]`: renders every
 * examples/*.kleinflow.json (or the named ones) to examples/png/NAME.png with the CPU interpreter
 * at the graph's own view and sample count, the graph embedded: plane examples two at a time on
 * worker threads, then space examples one at a time, each on every core.
 * `--thumbnails` writes the Examples gallery's small pictures instead (examples/thumbs/, no graph
 * inside) and records which version of each example they show (thumbs/sources.json), so a test
 * can tell a stale thumbnail. Prints name and time; exits 1 if any example fails.
 */
import { mkdir, readFile, writeFile } from 'node:fs/promises';
import { availableParallelism } from 'node:os';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { LIMITS } from '../../nodes/core/scene.ts';
import { parseArgs, parseSizeOption, stringOption } from './args.ts';
import { CliError } from './command.ts';
import {
  allExamples,
  EXAMPLES_3D_DIR,
  EXAMPLES_PNG_DIR,
  EXAMPLES_THUMB_DIR,
  exampleDigest,
  examplePath,
  THUMB_SOURCES,
} from './examples.ts';
import { type RenderJob, type RenderJobResult, render3dJob } from './render-job.ts';
import { runPool } from './worker-pool.ts';

const DEFAULT_SIZE = { width: 800, height: 800 };
/** Gallery thumbnails: small, square, enough samples to look smooth at that size. */
export const THUMB = { width: 192, height: 192, samples: 4 } as const;

async function main(argv: readonly string[]): Promise<number> {
  const parsed = parseArgs(argv, [
    { long: 'size', value: 'WxH', doc: 'image size (default 800x800)' },
    { long: 'thumbnails', doc: 'write the gallery thumbnails (examples/thumbs) instead' },
  ]);
  const thumbs = parsed.options.thumbnails === true;
  const sizeText = stringOption(parsed, 'size');
  const { width, height } = thumbs
    ? THUMB
    : sizeText
      ? parseSizeOption('size', sizeText, LIMITS.maxImageSide)
      : DEFAULT_SIZE;
  const outDir = thumbs ? EXAMPLES_THUMB_DIR : EXAMPLES_PNG_DIR;
  // Plane and space examples alike (3D ones are sphere traced by the CPU tracer: slower).
  const dirs = new Map(allExamples().map((e) => [e.name, e.dir]));
  const all = [...dirs.keys()];
  const names = parsed.positionals.length ? [...parsed.positionals] : all;
  const unknown = names.filter((n) => !dirs.has(n));
  if (unknown.length) throw new CliError(`no such example: ${unknown.join(', ')} (have: ${all.join(', ')})`);
  await mkdir(outDir, { recursive: true });
  const jobs: RenderJob[] = names.map((name) => ({
    name,
    input: examplePath(name, dirs.get(name)),
    output: join(outDir, `${name}.png`),
    width,
    height,
    samples: thumbs ? THUMB.samples : undefined,
    embedGraph: !thumbs,
  }));
  const rendered: string[] = [];
  const started = performance.now();
  let failed = 0;
  const report = (r: RenderJobResult) => {
    if (r.error !== undefined) {
      failed++;
      process.stderr.write(`${r.name.padEnd(28)} FAILED: ${r.error}\n`);
    } else {
      rendered.push(r.name);
      process.stdout.write(`${r.name.padEnd(28)} ${String(Math.round(r.ms)).padStart(6)} ms\n`);
    }
  };
  const in3d = (job: RenderJob) => dirs.get(job.name) === EXAMPLES_3D_DIR;
  const jobModule = new URL('./render-job.ts', import.meta.url);
  const plane = jobs.filter((job) => !in3d(job));
  await runPool<RenderJob, RenderJobResult>(jobModule, plane, Math.min(2, availableParallelism()), report);
  // Space examples one at a time, each split over every core.
  for (const job of jobs.filter(in3d)) report(await render3dJob(job, availableParallelism()));
  if (thumbs) await recordThumbSources(rendered, all);
  const total = ((performance.now() - started) / 1000).toFixed(1);
  process.stdout.write(
    `${jobs.length - failed} of ${jobs.length} examples → ${outDir} (${width}×${height}, ${total} s)\n`,
  );
  return failed ? 1 : 0;
}

/** Updates thumbs/sources.json for the rendered names, dropping examples that no longer exist. */
async function recordThumbSources(rendered: readonly string[], all: readonly string[]): Promise<void> {
  let sources: Record<string, string> = {};
  try {
    sources = JSON.parse(await readFile(THUMB_SOURCES, 'utf8')) as Record<string, string>;
  } catch {
    // first run: no record yet
  }
  const dirs = new Map(allExamples().map((e) => [e.name, e.dir]));
  for (const name of rendered) sources[name] = exampleDigest(name, dirs.get(name));
  const kept = Object.fromEntries(
    Object.entries(sources)
      .filter(([name]) => all.includes(name))
      .sort(([a], [b]) => a.localeCompare(b)),
  );
  await writeFile(THUMB_SOURCES, `${JSON.stringify(kept, null, 2)}\n`);
}

if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main(process.argv.slice(2)).then(
    (code) => {
      process.exitCode = code;
    },
    (e) => {
      process.stderr.write(`render-examples: ${e instanceof Error ? e.message : String(e)}\n`);
      process.exitCode = 1;
    },
  );
}
