/**
 * Formula: a number or a point computed from a typed formula (docs/formula.md) of the node's
 * inputs a, b, c (numbers), p, q (points) and the animation time t. The text is parsed by a
 * maintained parser and checked once (nodes/formula), never executed; a mistake is a KF327 on the
 * node naming the characters at fault, and the node's other output is left empty.
 */

import { defineNode } from '../core/define-node.ts';
import { diag } from '../core/diagnostics.ts';
import { type CompiledFormula, compileFormula } from '../formula/compile.ts';
import type { FormulaType } from '../formula/functions.ts';
import { FormulaError, MAX_FORMULA_LENGTH, parseFormula } from '../formula/parse.ts';
import { fail, fmt, pointInput } from './shared.ts';

/** The names a formula may use besides the constants, and their types. */
export const FORMULA_NAMES: Readonly<Record<string, FormulaType>> = {
  a: 'number',
  b: 'number',
  c: 'number',
  p: 'point',
  q: 'point',
  t: 'number',
};

/** Checked formulas by text: a drag re-evaluates the node every frame with the same text. */
const cache = new Map<string, CompiledFormula | FormulaError>();
const CACHE_SIZE = 256;

function compiled(text: string): CompiledFormula | FormulaError {
  const hit = cache.get(text);
  if (hit) return hit;
  let result: CompiledFormula | FormulaError;
  try {
    result = compileFormula(parseFormula(text), FORMULA_NAMES);
  } catch (e) {
    if (!(e instanceof FormulaError)) throw e;
    result = e;
  }
  if (cache.size >= CACHE_SIZE) cache.delete(cache.keys().next().value!);
  cache.set(text, result);
  return result;
}

/** Where in the text: “characters 5–7 (“foo”)”, or “at the end”. */
export function formulaPlace(text: string, [start, end]: readonly [number, number]): string {
  if (start >= text.length) return 'at the end';
  const piece = text.slice(start, Math.max(end, start + 1));
  const shown = piece.length > 24 ? `${piece.slice(0, 23)}…` : piece;
  return end - start > 1
    ? `characters ${start + 1}–${end} (“${shown}”)`
    : `character ${start + 1} (“${shown}”)`;
}

export const formulaNode = defineNode({
  type: 'formula',
  version: 1,
  label: 'Formula',
  category: 'Values',
  color: '#9aa5b1',
  doc:
    'A number or a point from a formula of a, b, c (numbers), p, q (points) and the time t: ' +
    'e.g. 360 / a, sqrt(a*a + b*b), mix(p, q, 0.5), rotate(q - p, pi / a) + p (Help lists what a formula may hold).',
  inputs: {
    a: { type: 'number', label: 'a', default: 1 },
    b: { type: 'number', label: 'b', default: 2 },
    c: { type: 'number', label: 'c', default: 3 },
    p: pointInput('p', 0, 0),
    q: pointInput('q', 1, 0),
  },
  outputs: {
    value: {
      type: 'number',
      label: 'number',
      optional: true,
      doc: 'the result when the formula gives a number',
    },
    point: {
      type: 'point',
      label: 'point',
      optional: true,
      doc: 'the result when the formula gives a point',
    },
  },
  params: {
    formula: {
      kind: 'string',
      default: 'a + b',
      maxLength: MAX_FORMULA_LENGTH,
      label: 'formula',
      doc: 'numbers, a b c p q t pi, + − * / % ** ( ), comparisons with c ? x : y, and functions such as sin, sqrt, min, max, mix, point, length, rotate',
    },
  },
  evaluate: ({ nodeId, inputs, params, time }) => {
    const text = params.formula;
    const formula = compiled(text);
    if (formula instanceof FormulaError)
      return {
        diagnostics: [diag('formula', { nodeId }, formula.message, formulaPlace(text, formula.span))],
      };
    const value = formula.run({ ...inputs, t: time });
    if (formula.type === 'number') {
      const n = value as number;
      if (!Number.isFinite(n))
        return fail(`the formula gives ${n} here (a division by 0, or sqrt/log of a negative?)`);
      return { outputs: { value: n }, readout: fmt(n) };
    }
    if (formula.type === 'point') {
      const [x, y] = value as readonly [number, number];
      if (!Number.isFinite(x) || !Number.isFinite(y))
        return fail(`the formula gives the point (${x}, ${y}) here (a division by 0?)`);
      return { outputs: { point: [x, y] }, readout: `(${fmt(x)}, ${fmt(y)})` };
    }
    return {
      diagnostics: [
        diag(
          'formula',
          { nodeId },
          'the formula is a comparison: give c ? x : y a number or point to choose',
          'as a whole',
        ),
      ],
    };
  },
});
