import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { compileFormula } from '../../../nodes/formula/compile.ts';
import { type FormulaType, type FormulaValue, FUNCTIONS } from '../../../nodes/formula/functions.ts';
import { FormulaError, parseFormula } from '../../../nodes/formula/parse.ts';

const NAMES: Record<string, FormulaType> = { a: 'number', b: 'number', p: 'point', q: 'point' };
const ENV = { a: 3, b: -2, p: [1, 2], q: [4, 6] } as Record<string, FormulaValue>;

const run = (text: string, env = ENV) => {
  const c = compileFormula(parseFormula(text), NAMES);
  return { type: c.type, value: c.run(env) };
};
function refused(text: string): { message: string; at: string } {
  try {
    compileFormula(parseFormula(text), NAMES);
  } catch (e) {
    if (!(e instanceof FormulaError)) throw e;
    return { message: e.message, at: text.slice(e.span[0], e.span[1]) };
  }
  throw new Error(`accepted: ${text}`);
}

describe('compileFormula', () => {
  it('computes numbers and points with the usual precedence', () => {
    expect(run('a + b * 2')).toEqual({ type: 'number', value: -1 });
    expect(run('-(a ** 2) + (-a) ** 2').value).toBe(0);
    expect(run('(a + b) ** 3')).toEqual({ type: 'number', value: 1 });
    expect(run('mod(-1, 3)').value).toBe(2);
    expect(run('q - p')).toEqual({ type: 'point', value: [3, 4] });
    expect(run('length(q - p)').value).toBe(5);
    expect(run('distance(p, q)').value).toBe(5);
    expect(run('2 * p + q / 2')).toEqual({ type: 'point', value: [4, 7] });
    expect(run('mix(p, q, 0.5)').value).toEqual([2.5, 4]);
    expect(run('point(a, b).y').value).toBe(-2);
    expect(run('a > b ? p : q').value).toEqual([1, 2]);
    expect(run('a > b && !(a == 3) ? 1 : 0').value).toBe(0);
    expect(run('max(a, b, 7, 1)').value).toBe(7);
    expect(run('clamp(a, 0, 1)').value).toBe(1);
    expect(run('degrees(atan2(1, 1))').value).toBeCloseTo(45, 12);
    expect(run('pi * 2 - tau').value).toBe(0);
    const r = run('rotate(point(1, 0), pi / 2)').value as readonly number[];
    expect(r[0]).toBeCloseTo(0, 15);
    expect(r[1]).toBeCloseTo(1, 15);
  });

  it('says which part has the wrong type, and what was expected', () => {
    expect(refused('a + p')).toMatchObject({
      at: 'a + p',
      message: expect.stringContaining('a number and a point'),
    });
    expect(refused('p * q').message).toContain('a point and a point');
    expect(refused('sin(p)')).toMatchObject({
      at: 'sin(p)',
      message: expect.stringContaining('sin(number)'),
    });
    expect(refused('mix(p, 1, 0)').message).toContain('mix(point, point, number)');
    expect(refused('a.x')).toMatchObject({ message: expect.stringContaining('needs a point') });
    expect(refused('d + 1')).toMatchObject({
      at: 'd',
      message: expect.stringContaining('the names are a, b, p, q'),
    });
    expect(refused('sin + 1').message).toContain('sin is a function');
    expect(refused('frobnicate(a)')).toMatchObject({ at: 'frobnicate' });
    expect(refused('a ? 1 : 2')).toMatchObject({ at: 'a' });
    expect(refused('a < b ? 1 : p').message).toContain('a number and a point');
    expect(refused('a < p').message).toContain('compares two numbers');
    expect(refused('a && b').message).toContain('joins two comparisons');
    expect(refused('-(a < b)').message).toContain('number or a point');
    expect(refused('min(a)').message).toContain('min(number, number, …)');
  });

  it('agrees with direct arithmetic on random number formulas (property)', () => {
    type Gen = { text: string; value: (a: number, b: number) => number };
    const leaf: fc.Arbitrary<Gen> = fc.oneof(
      fc.constant<Gen>({ text: 'a', value: (a) => a }),
      fc.constant<Gen>({ text: 'b', value: (_a, b) => b }),
      fc.integer({ min: -9, max: 9 }).map((k): Gen => ({ text: `(${k})`, value: () => k })),
    );
    const { expr } = fc.letrec<{ expr: Gen }>((tie) => ({
      expr: fc.oneof(
        { depthSize: 'small', withCrossShrink: true },
        leaf,
        fc.tuple(tie('expr'), fc.constantFrom('+', '-', '*'), tie('expr')).map(
          ([l, op, r]): Gen => ({
            text: `(${l.text} ${op} ${r.text})`,
            value: (a, b) =>
              op === '+'
                ? l.value(a, b) + r.value(a, b)
                : op === '-'
                  ? l.value(a, b) - r.value(a, b)
                  : l.value(a, b) * r.value(a, b),
          }),
        ),
        tie('expr').map((e): Gen => ({ text: `abs(${e.text})`, value: (a, b) => Math.abs(e.value(a, b)) })),
        fc.tuple(tie('expr'), tie('expr')).map(
          ([l, r]): Gen => ({
            text: `max(${l.text}, ${r.text})`,
            value: (a, b) => Math.max(l.value(a, b), r.value(a, b)),
          }),
        ),
      ),
    }));
    fc.assert(
      fc.property(
        expr,
        fc.double({ min: -5, max: 5, noNaN: true }),
        fc.double({ min: -5, max: 5, noNaN: true }),
        (g, a, b) => {
          const c = compileFormula(parseFormula(g.text), NAMES);
          expect(c.type).toBe('number');
          expect(c.run({ a, b })).toBe(g.value(a, b));
        },
      ),
      { seed: 11, numRuns: 500 },
    );
  });

  it('every function has a doc line and every signature runs on values of its types', () => {
    const sample: Record<FormulaType, FormulaValue> = { number: 0.5, point: [0.25, -0.75], truth: true };
    for (const [name, fn] of Object.entries(FUNCTIONS)) {
      expect(fn.doc.length, name).toBeGreaterThanOrEqual(3);
      for (const s of fn.signatures) {
        const v = s.run(s.args.map((t) => sample[t]));
        if (s.result === 'number') expect(typeof v, name).toBe('number');
        if (s.result === 'point') expect(Array.isArray(v) && v.length === 2, name).toBe(true);
      }
    }
  });
});
