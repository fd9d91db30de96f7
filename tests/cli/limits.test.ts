/**
 * Input limits and streaming of the real `kleinflow` executable: endless input (/dev/zero) is
 * refused in one line naming the limit, and `sample` answers points while they are still
 * arriving (so memory cannot grow with the number of points).
 */
import { spawn } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { pngChunk, pngWith, textData } from '../src/io/support/png-chunks.ts';
import { BIN, cliTempDir, graphText, ROOT, runCli, writeIn } from './run-cli.ts';

const dir = cliTempDir('kleinflow-limits-');

/** One inversion in the unit circle: the cheapest graph that samples (the test is about I/O). */
const GRAPH = writeIn(
  dir,
  'one-mirror.json',
  graphText(
    [
      { id: 'c', type: 'circle', position: [0, 0], params: { center: [0, 0], radius: 1 } },
      { id: 'i', type: 'inversion', position: [0, 0], params: {} },
      { id: 'out', type: 'render', position: [0, 0], params: {} },
    ],
    [
      { id: 'e1', from: { node: 'c', port: 'circle' }, to: { node: 'i', port: 'circle' } },
      { id: 'e2', from: { node: 'i', port: 'element' }, to: { node: 'out', port: 'elements' } },
    ],
  ),
);

describe('endless and oversized input', () => {
  it.each([
    [
      ['check', '/dev/zero'],
      /cannot read "\/dev\/zero": it is larger than 64 MB, the limit for a graph file/,
    ],
    [['sample', GRAPH, '--points', '/dev/zero'], /"\/dev\/zero" is not valid JSON/],
  ])('%j stops at once with one line', (args, message) => {
    const r = runCli(args); // runCli kills the child after 60 s: a hang fails here
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(message);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
  });

  it('says a points file is not UTF-8 (not "expected a Kleinflow document")', () => {
    const p = join(dir, 'latin1.json');
    writeFileSync(p, Buffer.from([0x5b, 0x5b, 0x30, 0xe9, 0x5d, 0x5d]));
    const r = runCli(['sample', GRAPH, '--points', p]);
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(/is not UTF-8 text: expected a JSON array of \[x, y\] points/);
  });
});

describe('kleinflow sample streams', () => {
  it('prints results while the points are still arriving, and all of them in order', async () => {
    const child = spawn(process.execPath, [BIN, 'sample', GRAPH, '--points', '-'], { cwd: ROOT });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (d) => {
      stdout += d;
    });
    child.stderr.on('data', (d) => {
      stderr += d;
    });
    child.stdin.on('error', () => {}); // a failed child closes its input: the assertions say why
    const exited = new Promise<number | null>((r) => child.on('close', r));
    // 20,000 points, then wait with the array still open: a reader that needs the whole input
    // first prints nothing until the end and this wait times out.
    const n = 20_000;
    const point = (i: number) => `[${(i % 400) / 100 - 2},0]`;
    child.stdin.write(`[${Array.from({ length: n }, (_, i) => point(i)).join(',')}`);
    const started = Date.now();
    while (stdout.length === 0 && Date.now() - started < 15_000) await new Promise((r) => setTimeout(r, 50));
    expect(stdout.length, `nothing printed before the input ended; stderr: ${stderr}`).toBeGreaterThan(0);
    child.stdin.end(`,${point(n)}]`);
    expect(await exited).toBe(0);
    const out = JSON.parse(stdout) as { points: { depth: number; x: number; y: number }[] };
    expect(out.points).toHaveLength(n + 1);
    // Spot checks: (0.5, 0) is inside the unit circle and inverts to (2, 0); (-2, 0) escapes at once.
    const inside = out.points[250];
    expect([inside.depth, inside.x, inside.y]).toEqual([1, 2, 0]);
    expect(out.points[0]).toEqual({ depth: 0, x: -2, y: 0, escaped: true });
  }, 30_000);
});

describe('PNG limits on the command line', () => {
  it.each(['check', 'convert'])(
    '%s refuses a PNG with a 2 MB text keyword in one line naming the file',
    (command) => {
      const path = join(dir, 'long-keyword.png');
      const keyword = new Uint8Array(2 * 1024 * 1024).fill(0x41);
      writeFileSync(path, pngWith([pngChunk('tEXt', textData(keyword, 'x'))]));
      const r = runCli([command, path]);
      expect(r.status).toBe(1);
      // check: one line; convert: the diagnostic, then "could not be converted". Never a stack trace.
      const lines = r.stderr.trim().split('\n');
      expect(lines.length).toBeLessThanOrEqual(2);
      expect(lines[0]).toMatch(/long-keyword\.png.*KF504.*keyword .*longer than 79 bytes/);
    },
  );
});
