/**
 * GLSL for a formula tree (docs/formula.md "In a shader"): the same parsed and type-checked tree
 * the CPU evaluates (nodes/formula), written out node by node. Nothing of the user's text is
 * pasted: a name becomes the GLSL expression the caller maps it to, a number goes through
 * floatLiteral, a function through the table below. Where GLSL's built-in differs from the CPU's
 * formula (pow of a negative base, round at halves, clamp with lo > hi, JavaScript's %), a helper
 * with the CPU's formula is used instead, so GPU and CPU agree.
 */
import { checkedFormula } from '../../nodes/formula/checked.ts';
import { CONSTANTS, type FormulaType } from '../../nodes/formula/functions.ts';
import { type Formula, FormulaError } from '../../nodes/formula/parse.ts';
import { floatLiteral } from './literal.ts';
import { type GlslFunction, glslFunction } from './snippet.ts';

/** xʸ as Math.pow: a negative base to an integer power keeps its sign rule; otherwise NaN-free 0. */
export const formulaPowGlsl = glslFunction(
  'kfPow',
  `
float kfPow(float x, float y) {
  if (x >= 0.0 || y != floor(y)) return pow(abs(x), y);
  float m = pow(-x, y);
  return mod(y, 2.0) == 0.0 ? m : -m;
}`,
);

/** JavaScript's %: x − y·trunc(x/y) (the sign of x). */
export const formulaRemGlsl = glslFunction(
  'kfRem',
  `
float kfRem(float x, float y) {
  return x - y * trunc(x / y);
}`,
);

/** p turned by θ about the origin. */
export const formulaRotateGlsl = glslFunction(
  'kfRotate',
  `
vec2 kfRotate(vec2 p, float t) {
  float c = cos(t);
  float s = sin(t);
  return vec2(c * p.x - s * p.y, s * p.x + c * p.y);
}`,
);

/** Functions whose GLSL built-in has the CPU's formula, by the same name unless mapped. */
const SAME: Readonly<Record<string, string>> = {
  abs: 'abs',
  sign: 'sign',
  sqrt: 'sqrt',
  exp: 'exp',
  log: 'log',
  sin: 'sin',
  cos: 'cos',
  tan: 'tan',
  asin: 'asin',
  acos: 'acos',
  atan: 'atan',
  atan2: 'atan',
  floor: 'floor',
  ceil: 'ceil',
  fract: 'fract',
  radians: 'radians',
  degrees: 'degrees',
  mod: 'mod',
  mix: 'mix',
  point: 'vec2',
  length: 'length',
  distance: 'distance',
  dot: 'dot',
};

const HELPERS: Readonly<Record<string, GlslFunction>> = {
  pow: formulaPowGlsl,
  rotate: formulaRotateGlsl,
};

export interface FormulaGlsl {
  readonly expr: string;
  /** Helper functions the expression calls. */
  readonly deps: readonly GlslFunction[];
}

/**
 * `float name(params)`: the number formula `text` (checked with `names`, its names mapped by
 * `glslNames` to the parameters), 0 where it does not check or is not finite — the colour
 * functions' twin of nodes/formula/checked.ts finiteValue.
 */
export function finiteFormulaFunction(
  name: string,
  params: string,
  text: string,
  names: Readonly<Record<string, FormulaType>>,
  glslNames: Readonly<Record<string, string>>,
): GlslFunction {
  const f = checkedFormula(text, names);
  const body =
    f instanceof FormulaError || f.type !== 'number'
      ? { expr: '0.0', deps: [] }
      : formulaGlsl(f.tree, glslNames);
  return glslFunction(
    name,
    `
float ${name}(${params}) {
  float v = ${body.expr};
  return isnan(v) || isinf(v) ? 0.0 : v;
}`,
    body.deps,
  );
}

/**
 * The GLSL expression of a type-checked formula. `names` maps each name the formula may use to a
 * GLSL expression (a parameter, a swizzle of one); constants become literals.
 */
export function formulaGlsl(tree: Formula, names: Readonly<Record<string, string>>): FormulaGlsl {
  const deps = new Set<GlslFunction>();
  const emit = (f: Formula): string => {
    switch (f.kind) {
      case 'number':
        return floatLiteral(f.value);
      case 'name': {
        const mapped = names[f.name];
        if (mapped !== undefined) return mapped;
        const constant = CONSTANTS[f.name];
        if (constant) return floatLiteral(constant.value);
        throw new Error(`formula name ${f.name} has no GLSL mapping`);
      }
      case 'unary':
        return `(${f.op}${emit(f.arg)})`;
      case 'binary': {
        const l = emit(f.left);
        const r = emit(f.right);
        if (f.op === '**') {
          deps.add(formulaPowGlsl);
          return `kfPow(${l}, ${r})`;
        }
        if (f.op === '%') {
          deps.add(formulaRemGlsl);
          return `kfRem(${l}, ${r})`;
        }
        return `(${l} ${f.op} ${r})`;
      }
      case 'field':
        return `${emit(f.of)}.${f.field}`;
      case 'choose':
        return `(${emit(f.test)} ? ${emit(f.yes)} : ${emit(f.no)})`;
      case 'call': {
        const args = f.args.map(emit);
        if (f.fn === 'min' || f.fn === 'max') return args.reduce((acc, a) => `${f.fn}(${acc}, ${a})`);
        // Math.round: halves up (GLSL's round leaves halves to the implementation).
        if (f.fn === 'round') return `floor(${args[0]} + 0.5)`;
        // min(max(x, lo), hi): GLSL's clamp is undefined for lo > hi.
        if (f.fn === 'clamp') return `min(max(${args[0]}, ${args[1]}), ${args[2]})`;
        const helper = HELPERS[f.fn];
        if (helper) {
          deps.add(helper);
          return `${helper.name}(${args.join(', ')})`;
        }
        const builtin = SAME[f.fn];
        if (!builtin) throw new Error(`formula function ${f.fn} has no GLSL form`);
        return `${builtin}(${args.join(', ')})`;
      }
    }
  };
  const expr = emit(tree);
  return { expr, deps: [...deps] };
}
