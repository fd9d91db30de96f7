/**
 * `kleinflow render` of a 3D graph through the real executable: on worker threads it writes the
 * bytes of one thread; it says its estimate before any progress, then progress (--progress forces
 * both on a render this small, which is otherwise silent: tests/cli/render-3d.test.ts); at the
 * largest size the estimate is the first line, said before the long work starts (the test stops
 * the render there). A volume render says so, with the samples its rays take, instead of "sphere
 * traced".
 */
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { BIN, cliTempDir, ROOT, runCli } from './run-cli.ts';

const FIG26 = join(ROOT, 'examples/3d/fig26-quasi-sphere.kleinflow.json');
const FIG10 = join(ROOT, 'examples/3d/fig10-volume-nesting-spheres.kleinflow.json');
const SMALL = ['--size', '20x16', '--samples', '1'];
const dir = cliTempDir('kleinflow-render3d-threads-');

/** The first line the command writes on stderr; the command is then killed. */
function firstStderrLine(args: readonly string[]): Promise<string> {
  const child = spawn(process.execPath, [BIN, ...args], { cwd: ROOT });
  return new Promise<string>((resolve, reject) => {
    let text = '';
    child.stderr.setEncoding('utf8');
    child.stderr.on('data', (chunk: string) => {
      text += chunk;
      const end = text.indexOf('\n');
      if (end >= 0) resolve(text.slice(0, end));
    });
    child.on('error', reject);
    child.on('exit', (code) => reject(new Error(`exited (${code}) before a line: ${text}`)));
  }).finally(() => child.kill('SIGKILL'));
}

describe('kleinflow render of a 3D graph on every core', () => {
  it('writes on 3 threads the bytes of 1, saying the estimate and then the progress', () => {
    const render = (threads: string) => {
      const out = join(dir, `t${threads}.png`);
      const r = runCli(['render', FIG26, '-o', out, ...SMALL, '--threads', threads, '--progress']);
      expect(r.status).toBe(0);
      return { png: readFileSync(out), lines: r.stderr.trim().split('\n') };
    };
    const many = render('3');
    const one = render('1');
    expect(many.png.equals(one.png)).toBe(true);
    const label = /^rendering .*t3\.png \(20×16, 1 samples\/px, sphere traced\)/;
    expect(many.lines[0]).toMatch(label);
    expect(many.lines[0]).toMatch(/: about .+ on 3 CPU threads \(estimated from a small probe render\)$/);
    const progress = many.lines.slice(1);
    expect(progress.map((line) => /(\d+)%/.exec(line)?.[1])).toEqual(['25', '50', '75']);
    for (const line of progress) expect(line).toMatch(label);
    expect(one.lines[0]).toMatch(/: about .+ on the CPU \(estimated/);
  }, 60_000);

  it('at 16384² says the estimate first, before the long work', async () => {
    const line = await firstStderrLine([
      'render',
      FIG26,
      '-o',
      join(dir, 'huge.png'),
      '--size',
      '16384x16384',
    ]);
    expect(line).toMatch(
      /^rendering .*huge\.png \(16384×16384, 4 samples\/px, sphere traced\): about \d+ h \d+ min on /,
    );
  }, 60_000);

  it('says a volume render is volume rendered, with the samples its rays take of those asked for', () => {
    const out = join(dir, 'volume.png');
    const r = runCli(['render', FIG10, '-o', out, ...SMALL, '--threads', '1', '--progress']);
    expect(r.status).toBe(0);
    const first = r.stderr.trim().split('\n')[0]!;
    expect(first).toMatch(
      /^rendering .*volume\.png \(20×16, 1 samples\/px, volume rendered, about \d+ of 128 samples per ray\): about /,
    );
    expect(first).not.toMatch(/sphere traced/);
  }, 60_000);
});
