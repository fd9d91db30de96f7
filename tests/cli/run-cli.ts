/**
 * Runs the real `kleinflow` executable as a child process (what a user's shell does), and what the
 * CLI test files share around it: a temporary folder per file and loading a graph file the way the
 * CLI does, to compute what it should have written.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, expect } from 'vitest';
import type { GraphDoc } from '../../nodes/graph/document.ts';
import { type Evaluation, evaluateGraph } from '../../nodes/graph/evaluate.ts';
import { parseDocumentText } from '../../nodes/graph/load.ts';
import { registry } from '../../nodes/types/index.ts';

export const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** The executable's script, for tests that talk to it while it runs (spawn). */
export const BIN = fileURLToPath(new URL('../../src/cli/kleinflow.mjs', import.meta.url));

export interface CliRun {
  readonly status: number | null;
  readonly stdout: string;
  readonly stderr: string;
}

export function runCli(args: readonly string[], cwd = ROOT): CliRun {
  const r = spawnSync(process.execPath, [BIN, ...args], { cwd, encoding: 'utf8', timeout: 60_000 });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

/** The path of examples/`name`.kleinflow.json. */
export const example = (name: string): string => join(ROOT, `examples/${name}.kleinflow.json`);

/** The text of a graph file with these nodes and edges (no title, the default view). */
export const graphText = (nodes: readonly unknown[], edges: readonly unknown[] = []): string =>
  JSON.stringify({
    format: 'kleinflow',
    version: 1,
    meta: {},
    nodes,
    edges,
    view: { center: [0, 0], scale: 4 },
  });

/** Runs the executable and expects it to succeed without a word on stderr. */
export function runCliOk(args: readonly string[], cwd = ROOT): CliRun {
  const run = runCli(args, cwd);
  expect(run.stderr).toBe('');
  expect(run.status).toBe(0);
  return run;
}

/**
 * A new temporary folder (named `prefix` and a random tail) for the test file that calls this at
 * its top level; it is removed after the file's tests.
 */
export function cliTempDir(prefix: string): string {
  const dir = mkdtempSync(join(tmpdir(), prefix));
  afterAll(() => rmSync(dir, { recursive: true, force: true }));
  return dir;
}

/** A graph file evaluated the way the CLI does it, with its document (throws when it does not load). */
export function evaluateFile(path: string): Evaluation & { readonly doc: GraphDoc } {
  const loaded = parseDocumentText(readFileSync(path, 'utf8'), registry);
  if (!loaded.ok) throw new Error(`${path} does not load`);
  return { ...evaluateGraph(loaded.doc, registry), doc: loaded.doc };
}

/** Writes `content` to the file `name` in `dir` and returns its path. */
export function writeIn(dir: string, name: string, content: string): string {
  const path = join(dir, name);
  writeFileSync(path, content);
  return path;
}
