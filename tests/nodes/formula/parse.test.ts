import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { FormulaError, MAX_FORMULA_DEPTH, parseFormula } from '../../../nodes/formula/parse.ts';

/** The span a refused formula names, as the text it covers. */
function refused(text: string): { message: string; at: string } {
  try {
    parseFormula(text);
  } catch (e) {
    if (!(e instanceof FormulaError)) throw e;
    return { message: e.message, at: text.slice(e.span[0], e.span[1]) };
  }
  throw new Error(`accepted: ${text}`);
}

describe('parseFormula', () => {
  it('reads numbers, names, operators, calls, fields and choices with their spans', () => {
    const f = parseFormula('a + 2 * sin(t)');
    expect(f).toMatchObject({ kind: 'binary', op: '+', span: [0, 14] });
    if (f.kind !== 'binary') throw new Error('binary');
    expect(f.right).toMatchObject({ kind: 'binary', op: '*', span: [4, 14] });
    expect(parseFormula('p.x')).toMatchObject({ kind: 'field', field: 'x' });
    expect(parseFormula('a < b ? a : b')).toMatchObject({ kind: 'choose' });
    expect(parseFormula('(a)')).toMatchObject({ kind: 'name', name: 'a', span: [1, 2] });
    expect(parseFormula('a === b')).toMatchObject({ kind: 'binary', op: '==' });
    expect(parseFormula('2 ** 3')).toMatchObject({ kind: 'binary', op: '**' });
  });

  it('refuses what is not part of the language, naming the characters at fault', () => {
    expect(refused('a ^ 2')).toMatchObject({ at: 'a ^ 2', message: expect.stringContaining('a ** 2') });
    expect(refused('"hi"')).toMatchObject({ at: '"hi"' });
    expect(refused('a = 3')).toMatchObject({ message: expect.stringContaining('assignment') });
    expect(refused('[1, 2]')).toMatchObject({ message: expect.stringContaining('point(x, y)') });
    expect(refused('Math.sin(a)').message).toContain('only the formula functions');
    expect(refused('p.z').message).toContain('.x and .y');
    expect(refused('p["x"]').message).toContain('.x and .y');
    expect(refused('a, b').message).toContain('one expression');
    expect(refused('a b')).toMatchObject({ at: 'b', message: expect.stringContaining('goes on after') });
    expect(refused('a +').message).toContain('cannot read');
    expect(refused('   ').message).toContain('empty');
    expect(refused('(() => 1)()').message).toContain('only the formula functions');
    expect(refused('x => x').message).toContain('function');
    expect(refused('this').message).toContain('not part of formulas');
    expect(refused('1n').message).toContain('only numbers');
    expect(refused('`a`').message).toContain('text template');
    expect(refused('sin(...a)').message).toContain('...');
    expect(refused('a ?? b').message).toContain('??');
    // JavaScript's rule, kept: a unary minus before ** must be bracketed.
    expect(refused('-a ** 2').message).toContain('cannot read');
  });

  it('bounds the nesting depth and the length', () => {
    const deep = `${'- '.repeat(MAX_FORMULA_DEPTH + 5)}a`;
    expect(refused(deep).message).toContain('nests deeper');
    expect(refused(`${'a+'.repeat(1200)}a`).message).toContain('longer than');
  });

  it('never throws anything but a FormulaError, whatever the text (fuzz)', () => {
    const pieces = [
      'a',
      'b',
      'p',
      '.x',
      '.y',
      '1',
      '2.5',
      '+',
      '-',
      '*',
      '/',
      '**',
      '^',
      '(',
      ')',
      ',',
      '?',
      ':',
      '<',
      '==',
      '&&',
      '!',
      'sin',
      'max',
      ' ',
      '"',
      '[',
      ']',
      '=',
      'e',
      'pi',
      '`',
      '{',
      '}',
    ];
    fc.assert(
      fc.property(
        fc.oneof(
          fc.string({ maxLength: 40 }),
          fc.array(fc.constantFrom(...pieces), { maxLength: 30 }).map((a) => a.join('')),
        ),
        (text) => {
          try {
            parseFormula(text);
          } catch (e) {
            expect(e).toBeInstanceOf(FormulaError);
            const { span } = e as FormulaError;
            expect(span[0]).toBeGreaterThanOrEqual(0);
            expect(span[1]).toBeLessThanOrEqual(Math.max(text.length, 1));
          }
        },
      ),
      { seed: 27, numRuns: 3000 },
    );
  });
});
