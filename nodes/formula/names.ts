/**
 * The names formulas may use besides the constants (docs/formula.md "Names"): the Formula node's
 * inputs a, b, c (numbers), p, q (points) and the time t; a seed shape adds the point tested,
 * z = (x, y).
 */
import type { FormulaType } from './functions.ts';
import { type Formula, parseFormula } from './parse.ts';

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

/** A 3D seed shape's names: the point tested, x, y, z (relative to the seed's centre), and a, b, c. */
export const SOLID_NAMES: Readonly<Record<string, FormulaType>> = {
  a: 'number',
  b: 'number',
  c: 'number',
  x: 'number',
  y: 'number',
  z: 'number',
};

/**
 * A colour function's names (the tile's `formula` colouring): the run's final point z = (x, y), its
 * depth n (inversions applied) and its accumulated scale s.
 */
export const COLOUR_NAMES: Readonly<Record<string, FormulaType>> = {
  z: 'point',
  x: 'number',
  y: 'number',
  n: 'number',
  s: 'number',
};

/** A 3D colour function's names: the hit point's x, y, z and its depth n (Render 3D's `formula` colouring). */
export const COLOUR_3D_NAMES: Readonly<Record<string, FormulaType>> = {
  x: 'number',
  y: 'number',
  z: 'number',
  n: 'number',
};

/** The node types whose `formula` param is a formula of FORMULA_NAMES (and the time t among them). */
export const FORMULA_NODE_TYPES: ReadonlySet<string> = new Set(['formula', 'seed-shape', 'seed-solid']);

/** Whether `text` reads the name `name` anywhere (false for a formula that does not parse). */
export function formulaUses(text: string, name: string): boolean {
  let tree: Formula;
  try {
    tree = parseFormula(text);
  } catch {
    return false;
  }
  const uses = (f: Formula): boolean => {
    switch (f.kind) {
      case 'number':
        return false;
      case 'name':
        return f.name === name;
      case 'unary':
        return uses(f.arg);
      case 'binary':
        return uses(f.left) || uses(f.right);
      case 'call':
        return f.args.some(uses);
      case 'field':
        return uses(f.of);
      case 'choose':
        return uses(f.test) || uses(f.yes) || uses(f.no);
    }
  };
  return uses(tree);
}
