#!/usr/bin/env node
// `npm test`: everything CI runs. Makes sure the system tools the browser, GLSL and slicer suites
// need are there (installing Debian's chromium, glslang-tools and prusa-slicer — PrusaSlicer reads
// the exported 3MF in tests/cli/mesh-prusa-slicer.test.ts — when we are root with apt), then runs
// the linter, the type checker and every Vitest suite, and ends with one "N passed, N failed" line.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync } from 'node:fs';

const CHROMIUM = process.env.KLEINFLOW_CHROMIUM ?? '/usr/bin/chromium';
const has = (cmd) => spawnSync('sh', ['-c', `command -v ${cmd}`], { stdio: 'ignore' }).status === 0;
const run = (cmd, args, opts = {}) => spawnSync(cmd, args, { stdio: 'inherit', ...opts }).status ?? 1;

function ensureSystemTools() {
  const missing = [];
  if (!existsSync(CHROMIUM)) missing.push('chromium');
  if (!has('glslangValidator')) missing.push('glslang-tools');
  if (!has('prusa-slicer')) missing.push('prusa-slicer');
  if (missing.length === 0) return;
  const root = typeof process.getuid === 'function' && process.getuid() === 0;
  if (root && has('apt-get')) {
    console.log(`[kleinflow] installing ${missing.join(' ')} with apt-get (once)…`);
    const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
    if (
      run('apt-get', ['update', '-qq'], { env }) === 0 &&
      run('apt-get', ['install', '-y', '-qq', ...missing], { env }) === 0
    )
      return;
  }
  console.error(
    `[kleinflow] the browser, GLSL and slicer tests need Debian's ${missing.join(' and ')}: run "sudo apt-get install -y ${missing.join(' ')}" and try again.`,
  );
  process.exit(1);
}

ensureSystemTools();
let failed = 0;
console.log('\n[kleinflow] lint (biome)');
failed |= run('npx', ['biome', 'check', '.']);
console.log('\n[kleinflow] type check (tsc)');
failed |= run('npx', ['tsc', '--noEmit', '-p', '.']);
console.log('\n[kleinflow] tests (vitest)');
mkdirSync('test-artifacts', { recursive: true });
const report = 'test-artifacts/vitest-report.json';
const vitest = run('npx', [
  'vitest',
  'run',
  '--reporter=default',
  '--reporter=json',
  `--outputFile.json=${report}`,
  ...process.argv.slice(2),
]);
let summary = '';
if (existsSync(report)) {
  const r = JSON.parse(readFileSync(report, 'utf8'));
  summary = `${r.numPassedTests} passed, ${r.numFailedTests} failed, ${r.numPendingTests + (r.numTodoTests ?? 0)} skipped`;
}
if (vitest !== 0 || failed !== 0) {
  if (failed !== 0) console.error('[kleinflow] lint or type check failed (see above)');
  console.log(summary || '0 passed, 1 failed');
  process.exit(1);
}
console.log(summary);
