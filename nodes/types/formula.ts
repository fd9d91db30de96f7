/**
 * Formula: a number or a point computed from a typed formula (docs/formula.md) of the node's
 * inputs a, b, c (numbers), p, q (points) and the animation time t. The text is parsed by a
 * maintained parser and checked once (nodes/formula), never executed; a mistake is a KF327 on the
 * node naming the characters at fault, and the node's other output is left empty.
 */

import { defineNode } from '../core/define-node.ts';
import { formulaFor } from '../formula/checked.ts';
import { FORMULA_NAMES } from '../formula/names.ts';
import { MAX_FORMULA_LENGTH } from '../formula/parse.ts';
import { fail, fmt, pointInput } from './shared.ts';

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
    const checked = formulaFor(
      nodeId,
      text,
      FORMULA_NAMES,
      ['number', 'point'],
      'the formula gives a number or a point (c ? x : y chooses one by a comparison)',
    );
    if ('problem' in checked) return { diagnostics: [checked.problem] };
    const { formula } = checked;
    const value = formula.run({ ...inputs, t: time });
    if (formula.type === 'number') {
      const n = value as number;
      if (!Number.isFinite(n))
        return fail(`the formula gives ${n} here (a division by 0, or sqrt/log of a negative?)`);
      return { outputs: { value: n }, readout: fmt(n) };
    }
    const [x, y] = value as readonly [number, number];
    if (!Number.isFinite(x) || !Number.isFinite(y))
      return fail(`the formula gives the point (${x}, ${y}) here (a division by 0?)`);
    return { outputs: { point: [x, y] }, readout: `(${fmt(x)}, ${fmt(y)})` };
  },
});
