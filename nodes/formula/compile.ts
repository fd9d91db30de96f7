/**
 * The formula language's type checker and CPU evaluator (docs/formula.md), in one walk of the
 * parsed tree: every name, operator and call is checked against the types of its operands (a
 * FormulaError with the span at fault otherwise) and becomes a closure, so a formula is checked
 * once and then run for every evaluation of its node with no further checks. Float64 throughout.
 */
import { CONSTANTS, type FormulaType, type FormulaValue, FUNCTIONS, type Signature } from './functions.ts';
import { type Formula, FormulaError } from './parse.ts';

type Env = Readonly<Record<string, FormulaValue>>;
type Run = (env: Env) => FormulaValue;

export interface CompiledFormula {
  readonly type: FormulaType;
  readonly run: Run;
}

/** How a type reads in a message. */
export const typeName = (t: FormulaType): string =>
  t === 'number' ? 'a number' : t === 'point' ? 'a point' : 'a comparison';

type P = readonly [number, number];
const asPoint = (v: FormulaValue) => v as P;

/** The arithmetic operators by operand types: result type and formula. */
function arithmetic(
  op: string,
  l: FormulaType,
  r: FormulaType,
): { type: FormulaType; run: (a: FormulaValue, b: FormulaValue) => FormulaValue } | null {
  if (l === 'number' && r === 'number') {
    const f: Record<string, (a: number, b: number) => number> = {
      '+': (a, b) => a + b,
      '-': (a, b) => a - b,
      '*': (a, b) => a * b,
      '/': (a, b) => a / b,
      '%': (a, b) => a % b,
      '**': (a, b) => a ** b,
    };
    const g = f[op];
    return g ? { type: 'number', run: (a, b) => g(a as number, b as number) } : null;
  }
  if (l === 'point' && r === 'point' && (op === '+' || op === '-')) {
    const k = op === '+' ? 1 : -1;
    return {
      type: 'point',
      run: (a, b) => [asPoint(a)[0] + k * asPoint(b)[0], asPoint(a)[1] + k * asPoint(b)[1]],
    };
  }
  if (op === '*' && l !== r && l !== 'truth' && r !== 'truth')
    return {
      type: 'point',
      run: (a, b) => {
        const [p, k] = l === 'point' ? [asPoint(a), b as number] : [asPoint(b), a as number];
        return [p[0] * k, p[1] * k];
      },
    };
  if (op === '/' && l === 'point' && r === 'number')
    return { type: 'point', run: (a, b) => [asPoint(a)[0] / (b as number), asPoint(a)[1] / (b as number)] };
  return null;
}

const COMPARE: Record<string, (a: number, b: number) => boolean> = {
  '<': (a, b) => a < b,
  '<=': (a, b) => a <= b,
  '>': (a, b) => a > b,
  '>=': (a, b) => a >= b,
  '==': (a, b) => a === b,
  '!=': (a, b) => a !== b,
};

/** The signature of `fn` that takes these argument types, or null. */
function pick(signatures: readonly Signature[], types: readonly FormulaType[]): Signature | null {
  return (
    signatures.find((s) => {
      if (s.repeats ? types.length < s.args.length : types.length !== s.args.length) return false;
      return types.every((t, i) => t === s.args[Math.min(i, s.args.length - 1)]);
    }) ?? null
  );
}

const usage = (fn: string, s: Signature) =>
  `${fn}(${s.args.map((a) => a).join(', ')}${s.repeats ? ', …' : ''})`;

/**
 * Checks the tree against the types of the names the node provides (`names`; the constants pi,
 * tau, e are always there) and returns its type and the closure that evaluates it.
 */
export function compileFormula(f: Formula, names: Readonly<Record<string, FormulaType>>): CompiledFormula {
  switch (f.kind) {
    case 'number':
      return { type: 'number', run: () => f.value };
    case 'name': {
      const type = names[f.name];
      if (type) return { type, run: (env) => env[f.name]! };
      const constant = CONSTANTS[f.name];
      if (constant) return { type: 'number', run: () => constant.value };
      const known = [...Object.keys(names), ...Object.keys(CONSTANTS)].join(', ');
      const hint = FUNCTIONS[f.name] ? ` (${f.name} is a function: ${f.name}(…))` : '';
      throw new FormulaError(
        `“${f.name}” is not a name formulas know${hint}; the names are ${known}`,
        f.span,
      );
    }
    case 'unary': {
      const arg = compileFormula(f.arg, names);
      if (f.op === '!') {
        if (arg.type !== 'truth')
          throw new FormulaError(`“!” needs a comparison, not ${typeName(arg.type)}`, f.span);
        return { type: 'truth', run: (env) => !arg.run(env) };
      }
      if (arg.type === 'truth') throw new FormulaError(`“${f.op}” needs a number or a point`, f.span);
      const k = f.op === '-' ? -1 : 1;
      return arg.type === 'number'
        ? { type: 'number', run: (env) => k * (arg.run(env) as number) }
        : { type: 'point', run: (env) => [k * asPoint(arg.run(env))[0], k * asPoint(arg.run(env))[1]] };
    }
    case 'binary': {
      const l = compileFormula(f.left, names);
      const r = compileFormula(f.right, names);
      if (f.op === '&&' || f.op === '||') {
        if (l.type !== 'truth' || r.type !== 'truth')
          throw new FormulaError(`“${f.op}” joins two comparisons`, f.span);
        return f.op === '&&'
          ? { type: 'truth', run: (env) => (l.run(env) as boolean) && (r.run(env) as boolean) }
          : { type: 'truth', run: (env) => (l.run(env) as boolean) || (r.run(env) as boolean) };
      }
      const compare = COMPARE[f.op];
      if (compare) {
        if (l.type !== 'number' || r.type !== 'number')
          throw new FormulaError(
            `“${f.op}” compares two numbers, not ${typeName(l.type)} and ${typeName(r.type)}`,
            f.span,
          );
        return { type: 'truth', run: (env) => compare(l.run(env) as number, r.run(env) as number) };
      }
      const op = arithmetic(f.op, l.type, r.type);
      if (!op)
        throw new FormulaError(`“${f.op}” cannot take ${typeName(l.type)} and ${typeName(r.type)}`, f.span);
      return { type: op.type, run: (env) => op.run(l.run(env), r.run(env)) };
    }
    case 'field': {
      const of = compileFormula(f.of, names);
      if (of.type !== 'point')
        throw new FormulaError(`.${f.field} needs a point, not ${typeName(of.type)}`, f.span);
      const i = f.field === 'x' ? 0 : 1;
      return { type: 'number', run: (env) => asPoint(of.run(env))[i]! };
    }
    case 'choose': {
      const test = compileFormula(f.test, names);
      if (test.type !== 'truth')
        throw new FormulaError(
          `before “?” comes a comparison (a < b …), not ${typeName(test.type)}`,
          f.test.span,
        );
      const a = compileFormula(f.yes, names);
      const b = compileFormula(f.no, names);
      if (a.type !== b.type || a.type === 'truth')
        throw new FormulaError(
          `both sides of “:” must be numbers or both points (here ${typeName(a.type)} and ${typeName(b.type)})`,
          f.span,
        );
      return { type: a.type, run: (env) => (test.run(env) ? a.run(env) : b.run(env)) };
    }
    case 'call': {
      const fn = FUNCTIONS[f.fn];
      if (!fn) {
        const known = Object.keys(FUNCTIONS).join(', ');
        throw new FormulaError(`“${f.fn}” is not a formula function; they are ${known}`, f.fnSpan);
      }
      const args = f.args.map((a) => compileFormula(a, names));
      const signature = pick(
        fn.signatures,
        args.map((a) => a.type),
      );
      if (!signature) {
        const forms = fn.signatures.map((s) => usage(f.fn, s)).join(' or ');
        throw new FormulaError(`${f.fn} takes ${forms}, not (${args.map((a) => a.type).join(', ')})`, f.span);
      }
      // One argument buffer per call site, filled at each run (no array per call: a seed shape
      // runs at every IIS step of every pixel). Safe: a call site never runs inside its own arguments.
      const buffer: FormulaValue[] = new Array(args.length);
      return {
        type: signature.result,
        run: (env) => {
          for (let i = 0; i < args.length; i++) buffer[i] = args[i]!.run(env);
          return signature.run(buffer);
        },
      };
    }
  }
}
