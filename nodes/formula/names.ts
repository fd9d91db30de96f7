/**
 * The names formulas may use besides the constants (docs/formula.md "Names"): the Formula node's
 * inputs a, b, c (numbers), p, q (points) and the time t; a seed shape adds the point tested,
 * z = (x, y).
 */
import type { FormulaType } from './functions.ts';

export const FORMULA_NAMES: Readonly<Record<string, FormulaType>> = {
  a: 'number',
  b: 'number',
  c: 'number',
  p: 'point',
  q: 'point',
  t: 'number',
};

export const SHAPE_NAMES: Readonly<Record<string, FormulaType>> = {
  ...FORMULA_NAMES,
  z: 'point',
  x: 'number',
  y: 'number',
};
