/**
 * `kleinflow check` on a sample of the fuzz documents, through the real executable: it exits 0 or
 * 1, prints a one-line summary per file that agrees with the in-process pipeline, and never shows
 * a stack trace to the user, whatever the file holds.
 */
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import fc from 'fast-check';
import { afterAll, describe, expect, it } from 'vitest';
import { hasErrors } from '../../nodes/core/diagnostics.ts';
import { runCli } from '../cli/run-cli.ts';
import { mutatedExample, readExamples, skeletonDocument } from './document-arbitraries.ts';
import { checkPipeline } from './pipeline-check.ts';

const dir = mkdtempSync(join(tmpdir(), 'kleinflow-fuzz-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** 30 documents: 10 arbitrary JSON texts, 10 skeleton documents, 10 mutated examples (fixed seeds). */
function sampleFiles(): { path: string; text: string }[] {
  const texts = [
    ...fc.sample(fc.jsonValue(), { seed: 7, numRuns: 10 }).map((v) => JSON.stringify(v) ?? 'null'),
    ...fc.sample(skeletonDocument, { seed: 7, numRuns: 10 }).map((v) => JSON.stringify(v)),
    ...fc.sample(mutatedExample(readExamples()), { seed: 7, numRuns: 10 }).map((m) => m.text),
  ];
  // And pathological files: 10,000-level nesting, a 10 MB title.
  texts[0] = `${'['.repeat(10_000)}${']'.repeat(10_000)}`;
  texts[1] = JSON.stringify({ ...readExamples()[0].doc, meta: { title: 'x'.repeat(10 * 1024 * 1024) } });
  return texts.map((text, i) => {
    const path = join(dir, `fuzz-${String(i).padStart(2, '0')}.kleinflow.json`);
    writeFileSync(path, text);
    return { path, text };
  });
}

const STACK_LINE = /^\s{4}at /m;

describe('kleinflow check on fuzzed files', () => {
  const files = sampleFiles();

  it('checks 30 hostile files in one run: exit 0/1, a summary per file, no stack trace', () => {
    const r = runCli(['check', ...files.map((f) => f.path)]);
    expect([0, 1]).toContain(r.status);
    expect(r.stdout).not.toMatch(STACK_LINE);
    expect(r.stderr).not.toMatch(STACK_LINE);
    expect(r.stderr).not.toMatch(/internal error/);
    let anyError = false;
    for (const { path, text } of files) {
      const summary = r.stderr.split('\n').find((l) => l.startsWith(`${path}: `));
      expect(summary, path).toBeDefined();
      const expectedError = hasErrors(checkPipeline({ text }).diagnostics);
      anyError ||= expectedError;
      // "ok" or "N errors, M warnings": errors exactly when the pipeline found some.
      expect(/ 0 errors|: ok$/.test(summary!), `${summary}`).toBe(!expectedError);
    }
    expect(r.status).toBe(anyError ? 1 : 0);
  }, 120_000);

  it('gives each file on its own the exit status its diagnostics call for', () => {
    for (const { path, text } of [files[0], files[12], files[25]]) {
      const r = runCli(['check', path]);
      expect(r.status).toBe(hasErrors(checkPipeline({ text }).diagnostics) ? 1 : 0);
      expect(`${r.stdout}${r.stderr}`).not.toMatch(STACK_LINE);
    }
  }, 120_000);
});
