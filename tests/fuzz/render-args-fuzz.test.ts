/**
 * The animation export settings as command-line input (`kleinflow render --time/--frames/--fps/
 * --frame-range/--threads/--out`), fuzzed in process: whatever is typed, the command answers with
 * exit 0, 1 or 2 and, when it refuses, one short message naming the option — never a stack trace,
 * never an internal error. Frame ranges are drawn so that an accepted command renders at most one
 * 2×2 frame (the point is the parsing, not the rendering).
 */
import { readFileSync } from 'node:fs';
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { examplePath } from '../../src/cli/examples.ts';
import { main } from '../../src/cli/main.ts';
import { memoryIo } from '../support/memory-io.ts';

const GRAPH = readFileSync(examplePath('animated-breathing-loxodromic'), 'utf8');
const hostile = [
  '',
  ' ',
  '0',
  '-1',
  '1e309',
  'NaN',
  'Infinity',
  '-0',
  '1.5',
  'abc',
  '١٢',
  '9'.repeat(40),
  '\u0000',
];
const time = fc.constantFrom(...hostile, '2.5', '-3', '1e6');
const frames = fc.constantFrom(...hostile, '1', '2', 'loop', 'LOOP', '100000000');
const fps = fc.constantFrom(...hostile, '24', '0.001', '1000000');
const range = fc.constantFrom(
  '0:1',
  '1:2',
  '1:0',
  '0:0',
  ':',
  'a:b',
  '-1:1',
  '3',
  '0:1:2',
  '',
  '99999999:100000000',
);
const threads = fc.constantFrom('1', '0', '-2', 'x', '');
const out = fc.constantFrom('frames/', 'x.gif', 'x.png', '', 'x.GIF');

const STACK_LINE = /^\s{4}at /m;

async function run(args: string[]) {
  const { io, out: printed } = memoryIo({ 'anim.json': GRAPH });
  const status = await main(['render', 'anim.json', ...args], io);
  return { status, ...printed };
}

function expectCalmAnswer(r: { status: number; stdout: string; stderr: string }, args: string[]) {
  const what = args.join(' ');
  expect([0, 1, 2], what).toContain(r.status);
  expect(`${r.stdout}${r.stderr}`, what).not.toMatch(STACK_LINE);
  expect(r.stderr, what).not.toMatch(/internal error/i);
  if (r.status !== 0) expect(r.stderr.trim().length, what).toBeGreaterThan(0);
}

describe('kleinflow render: fuzzed animation settings', () => {
  it('a still at any --time answers calmly', async () => {
    const cases = fc.sample(time, { seed: 11, numRuns: 20 });
    for (const t of cases) {
      const args = ['-o', 'still.png', '--size', '2x2', '--samples', '1', '--time', t];
      expectCalmAnswer(await run(args), args);
    }
  }, 60_000);

  it('any --frames / --fps / --frame-range / --threads / --out answers calmly', async () => {
    const combos = fc.sample(fc.tuple(frames, fps, range, threads, out), { seed: 12, numRuns: 40 });
    let refused = 0;
    for (const [f, r, g, t, o] of combos) {
      const args = [
        '--size',
        '2x2',
        '--samples',
        '1',
        '--frames',
        f,
        '--fps',
        r,
        '--frame-range',
        g,
        '--threads',
        t,
        '--out',
        o,
      ];
      const result = await run(args);
      expectCalmAnswer(result, args);
      if (result.status !== 0) refused++;
    }
    // Most combinations are nonsense and must be refused; a few are fine.
    expect(refused).toBeGreaterThan(20);
  }, 120_000);
});
