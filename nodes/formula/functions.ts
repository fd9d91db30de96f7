/**
 * The formula language's functions and names (docs/formula.md), declared once: each function's
 * signatures (argument types → result type) and its float64 formula. The type checker and the
 * evaluator read only this table, so adding a function is one entry here (and one line in the
 * grammar document, which a test keeps in step).
 */
import type { Vec2 } from '../core/values.ts';

/** A value's type: a number, a point (x, y) or a truth (from comparisons, for `c ? a : b`). */
export type FormulaType = 'number' | 'point' | 'truth';
export type FormulaValue = number | Vec2 | boolean;

export interface Signature {
  readonly args: readonly FormulaType[];
  /** The last argument type may repeat (min, max): at least `args.length` arguments. */
  readonly repeats?: true;
  readonly result: FormulaType;
  readonly run: (args: readonly FormulaValue[]) => FormulaValue;
}

export interface FormulaFunction {
  readonly doc: string;
  readonly signatures: readonly Signature[];
}

type N = number;
const num = (f: (x: N) => N, doc: string): FormulaFunction => ({
  doc,
  signatures: [{ args: ['number'], result: 'number', run: (a) => f(a[0] as N) }],
});
const num2 = (f: (x: N, y: N) => N, doc: string): FormulaFunction => ({
  doc,
  signatures: [{ args: ['number', 'number'], result: 'number', run: (a) => f(a[0] as N, a[1] as N) }],
});
const pt = (v: FormulaValue) => v as Vec2;

/** mix(a, b, t) = a + (b − a)·t. */
const lerp = (a: N, b: N, t: N) => a + (b - a) * t;

export const FUNCTIONS: Readonly<Record<string, FormulaFunction>> = {
  abs: num(Math.abs, '|x|'),
  sign: num(Math.sign, '−1, 0 or 1'),
  sqrt: num(Math.sqrt, '√x (x ≥ 0)'),
  exp: num(Math.exp, 'eˣ, e to the power x'),
  log: num(Math.log, 'natural logarithm (x > 0)'),
  sin: num(Math.sin, 'sine, x in radians'),
  cos: num(Math.cos, 'cosine, x in radians'),
  tan: num(Math.tan, 'tangent, x in radians'),
  asin: num(Math.asin, 'arc sine, in radians'),
  acos: num(Math.acos, 'arc cosine, in radians'),
  atan: num(Math.atan, 'arc tangent, in radians'),
  floor: num(Math.floor, 'largest integer ≤ x'),
  ceil: num(Math.ceil, 'smallest integer ≥ x'),
  round: num(Math.round, 'nearest integer (halves up)'),
  fract: num((x) => x - Math.floor(x), 'x − floor(x)'),
  radians: num((d) => (d * Math.PI) / 180, 'degrees to radians'),
  degrees: num((r) => (r * 180) / Math.PI, 'radians to degrees'),
  atan2: num2(Math.atan2, 'angle of (x, y) from the x axis: atan2(y, x), in radians'),
  pow: num2(Math.pow, 'xʸ, x to the power y'),
  mod: num2((x, y) => x - y * Math.floor(x / y), 'x − y·floor(x/y) (the sign of y, like GLSL)'),
  min: {
    doc: 'the smallest of two or more numbers',
    signatures: [
      { args: ['number', 'number'], repeats: true, result: 'number', run: (a) => Math.min(...(a as N[])) },
    ],
  },
  max: {
    doc: 'the largest of two or more numbers',
    signatures: [
      { args: ['number', 'number'], repeats: true, result: 'number', run: (a) => Math.max(...(a as N[])) },
    ],
  },
  clamp: {
    doc: 'x kept within [lo, hi]: min(max(x, lo), hi)',
    signatures: [
      {
        args: ['number', 'number', 'number'],
        result: 'number',
        run: (a) => Math.min(Math.max(a[0] as N, a[1] as N), a[2] as N),
      },
    ],
  },
  mix: {
    doc: 'a + (b − a)·t, for numbers or points',
    signatures: [
      {
        args: ['number', 'number', 'number'],
        result: 'number',
        run: (a) => lerp(a[0] as N, a[1] as N, a[2] as N),
      },
      {
        args: ['point', 'point', 'number'],
        result: 'point',
        run: (a) => [lerp(pt(a[0])[0], pt(a[1])[0], a[2] as N), lerp(pt(a[0])[1], pt(a[1])[1], a[2] as N)],
      },
    ],
  },
  point: {
    doc: 'the point (x, y)',
    signatures: [{ args: ['number', 'number'], result: 'point', run: (a) => [a[0] as N, a[1] as N] }],
  },
  length: {
    doc: 'the distance of p from the origin, √(x² + y²)',
    signatures: [{ args: ['point'], result: 'number', run: (a) => Math.hypot(pt(a[0])[0], pt(a[0])[1]) }],
  },
  distance: {
    doc: 'the distance |q − p|',
    signatures: [
      {
        args: ['point', 'point'],
        result: 'number',
        run: (a) => Math.hypot(pt(a[1])[0] - pt(a[0])[0], pt(a[1])[1] - pt(a[0])[1]),
      },
    ],
  },
  dot: {
    doc: 'p·q = pₓqₓ + p_y q_y',
    signatures: [
      {
        args: ['point', 'point'],
        result: 'number',
        run: (a) => pt(a[0])[0] * pt(a[1])[0] + pt(a[0])[1] * pt(a[1])[1],
      },
    ],
  },
  rotate: {
    doc: 'p turned by angle θ (radians) about the origin',
    signatures: [
      {
        args: ['point', 'number'],
        result: 'point',
        run: (a) => {
          const [x, y] = pt(a[0]);
          const c = Math.cos(a[1] as N);
          const s = Math.sin(a[1] as N);
          return [c * x - s * y, s * x + c * y];
        },
      },
    ],
  },
};

/** Named constants (the inputs are named by the node: a, b, c, p, q, t). */
export const CONSTANTS: Readonly<Record<string, { readonly value: number; readonly doc: string }>> = {
  pi: { value: Math.PI, doc: 'π = 3.14159…' },
  tau: { value: 2 * Math.PI, doc: 'τ = 2π' },
  e: { value: Math.E, doc: 'e = 2.71828…' },
};
