/**
 * Points-file fuzzing: arbitrary text, arbitrary JSON and near-valid point lists go through the
 * streaming reader (src/cli/points-stream.ts) split into random pieces. It must agree with
 * JSON.parse on every valid `[[x, y], …]` and end every other input with a CliError (a message for
 * the user), never another exception.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { CliError } from '../../src/cli/command.ts';
import { streamPoints } from '../../src/cli/points-stream.ts';

async function read(
  text: string,
  cuts: number[],
): Promise<{ points?: (readonly number[])[]; error?: unknown }> {
  const bytes = new TextEncoder().encode(text);
  const at = [...new Set(cuts.map((c) => c % (bytes.length + 1)))].sort((a, b) => a - b);
  async function* pieces() {
    let last = 0;
    for (const c of [...at, bytes.length]) {
      yield bytes.subarray(last, c);
      last = c;
    }
  }
  const points: (readonly number[])[] = [];
  try {
    for await (const batch of streamPoints('p.json', pieces())) points.push(...batch);
    return { points };
  } catch (error) {
    return { error };
  }
}

const isPointList = (v: unknown): v is number[][] =>
  Array.isArray(v) &&
  v.every(
    (p) => Array.isArray(p) && p.length === 2 && p.every((c) => typeof c === 'number' && Number.isFinite(c)),
  );

const finite = fc.double({ noNaN: true, noDefaultInfinity: true });
const pointsText = fc
  .tuple(fc.array(fc.tuple(finite, finite), { maxLength: 30 }), fc.constantFrom('', ' ', '\n  '))
  .map(([ps, ws]) => `${ws}[${ps.map(([x, y]) => `${ws}[${x},${ws}${y}]`).join(`,${ws}`)}${ws}]${ws}`);
const mutated = fc
  .tuple(pointsText, fc.nat(), fc.constantFrom('', ',', ']', '[', '"', '}', 'x', '\\', '\u00e9'))
  .map(([t, at, insert]) => t.slice(0, at % (t.length + 1)) + insert + t.slice(at % (t.length + 1)));

async function agreesWithJsonParse(text: string, cuts: number[]) {
  const got = await read(text, cuts);
  let expected: unknown;
  let valid = true;
  try {
    expected = JSON.parse(text);
  } catch {
    valid = false;
  }
  if (valid && isPointList(expected)) {
    expect(got.error).toBeUndefined();
    expect(got.points).toEqual(expected);
  } else {
    expect(got.error).toBeInstanceOf(CliError);
  }
}

describe('points-file fuzzing (streamed in random pieces)', () => {
  it('valid, mutated and arbitrary inputs: the right points or one CliError', async () => {
    const cuts = fc.array(fc.nat(), { maxLength: 6 });
    for (const arb of [
      pointsText,
      mutated,
      fc.string({ maxLength: 60 }),
      fc.jsonValue().map((v) => JSON.stringify(v) ?? ''),
    ]) {
      await fc.assert(fc.asyncProperty(arb, cuts, agreesWithJsonParse), { seed: 42, numRuns: 400 });
    }
  }, 60_000);
});
