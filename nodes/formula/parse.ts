/**
 * The formula language's parser (docs/formula.md): the text is read by acorn, a maintained
 * JavaScript parser that gives every node its character span, as ONE expression, and only the
 * small subset the language allows is turned into a Formula tree — numbers, names, + − × ÷ % and
 * ** (power), comparisons, && || !, `c ? a : b`, calls of the known functions and `.x`/`.y`.
 * Everything else (strings, assignments, objects, `this`, member calls …) is refused with a
 * FormulaError naming its span. The text is never executed: the tree is evaluated by
 * ./evaluate.ts and nothing else.
 */
import { type Expression, parseExpressionAt } from 'acorn';

/** Characters [start, end) of the formula text. */
export type Span = readonly [number, number];

export class FormulaError extends Error {
  constructor(
    message: string,
    readonly span: Span,
  ) {
    super(message);
  }
}

export type BinaryOp =
  | '+'
  | '-'
  | '*'
  | '/'
  | '%'
  | '**'
  | '<'
  | '<='
  | '>'
  | '>='
  | '=='
  | '!='
  | '&&'
  | '||';
export type UnaryOp = '-' | '+' | '!';

export type Formula =
  | { readonly kind: 'number'; readonly value: number; readonly span: Span }
  | { readonly kind: 'name'; readonly name: string; readonly span: Span }
  | { readonly kind: 'unary'; readonly op: UnaryOp; readonly arg: Formula; readonly span: Span }
  | {
      readonly kind: 'binary';
      readonly op: BinaryOp;
      readonly left: Formula;
      readonly right: Formula;
      readonly span: Span;
    }
  | {
      readonly kind: 'call';
      readonly fn: string;
      readonly fnSpan: Span;
      readonly args: readonly Formula[];
      readonly span: Span;
    }
  | { readonly kind: 'field'; readonly of: Formula; readonly field: 'x' | 'y'; readonly span: Span }
  | {
      readonly kind: 'choose';
      readonly test: Formula;
      readonly yes: Formula;
      readonly no: Formula;
      readonly span: Span;
    };

/** Longest formula accepted (a formula is a line or two, not a program). */
export const MAX_FORMULA_LENGTH = 2000;
/** Deepest nesting accepted (keeps every walk of the tree far from the stack limit). */
export const MAX_FORMULA_DEPTH = 64;

const BINARY = new Set<string>([
  '+',
  '-',
  '*',
  '/',
  '%',
  '**',
  '<',
  '<=',
  '>',
  '>=',
  '==',
  '!=',
  '===',
  '!==',
]);

const spanOf = (n: { start: number; end: number }): Span => [n.start, n.end];

function convert(n: Expression, depth: number): Formula {
  if (depth > MAX_FORMULA_DEPTH)
    throw new FormulaError(`the formula nests deeper than ${MAX_FORMULA_DEPTH} levels`, spanOf(n));
  const span = spanOf(n);
  const next = (e: Expression) => convert(e, depth + 1);
  switch (n.type) {
    case 'Literal':
      if (typeof n.value === 'number') return { kind: 'number', value: n.value, span };
      throw new FormulaError('only numbers can be written as values here', span);
    case 'Identifier':
      return { kind: 'name', name: n.name, span };
    case 'UnaryExpression':
      if (n.operator === '-' || n.operator === '+' || n.operator === '!')
        return { kind: 'unary', op: n.operator, arg: next(n.argument), span };
      throw new FormulaError(`“${n.operator}” is not an operator of formulas`, span);
    case 'BinaryExpression': {
      if (n.operator === '^')
        throw new FormulaError('“^” is not a power here: write a ** 2 or pow(a, 2)', span);
      if (!BINARY.has(n.operator) || n.left.type === 'PrivateIdentifier')
        throw new FormulaError(`“${n.operator}” is not an operator of formulas`, span);
      const op = (n.operator === '===' ? '==' : n.operator === '!==' ? '!=' : n.operator) as BinaryOp;
      return { kind: 'binary', op, left: next(n.left), right: next(n.right), span };
    }
    case 'LogicalExpression':
      if (n.operator === '??') throw new FormulaError('“??” is not an operator of formulas', span);
      return { kind: 'binary', op: n.operator, left: next(n.left), right: next(n.right), span };
    case 'ConditionalExpression':
      return {
        kind: 'choose',
        test: next(n.test),
        yes: next(n.consequent),
        no: next(n.alternate),
        span,
      };
    case 'CallExpression':
      if (n.callee.type !== 'Identifier' || n.optional)
        throw new FormulaError(
          'only the formula functions can be called, by name: sin(a), max(a, b) …',
          span,
        );
      return {
        kind: 'call',
        fn: n.callee.name,
        fnSpan: spanOf(n.callee),
        args: n.arguments.map((a) => {
          if (a.type === 'SpreadElement') throw new FormulaError('“...” is not part of formulas', spanOf(a));
          return next(a);
        }),
        span,
      };
    case 'MemberExpression':
      if (
        !n.computed &&
        !n.optional &&
        n.property.type === 'Identifier' &&
        (n.property.name === 'x' || n.property.name === 'y')
      ) {
        if (n.object.type === 'Super') throw new FormulaError('“super” is not part of formulas', span);
        return { kind: 'field', of: next(n.object), field: n.property.name, span };
      }
      throw new FormulaError('only .x and .y can follow a point', span);
    case 'ParenthesizedExpression':
      return next(n.expression);
    default:
      throw new FormulaError(`this is not part of formulas (${describe(n.type)})`, span);
  }
}

/** What people would call an acorn node type they wrote by accident. */
function describe(type: string): string {
  if (type.includes('Assignment') || type === 'UpdateExpression') return 'assignment';
  if (type === 'ArrayExpression') return 'a list: write point(x, y) for a point';
  if (type === 'ArrowFunctionExpression' || type === 'FunctionExpression') return 'a function';
  if (type === 'TemplateLiteral') return 'a text template';
  if (type === 'SequenceExpression') return 'a comma list: one expression only';
  return type.replace(/([a-z])([A-Z])/g, '$1 $2').toLowerCase();
}

/** Parses formula text into a tree, or throws a FormulaError with the span at fault. */
export function parseFormula(text: string): Formula {
  if (text.length > MAX_FORMULA_LENGTH)
    throw new FormulaError(`the formula is longer than ${MAX_FORMULA_LENGTH} characters`, [0, text.length]);
  if (text.trim() === '') throw new FormulaError('the formula is empty', [0, text.length]);
  let expr: Expression;
  try {
    expr = parseExpressionAt(text, 0, { ecmaVersion: 2022, preserveParens: true });
  } catch (e) {
    const pos = typeof (e as { pos?: unknown }).pos === 'number' ? (e as { pos: number }).pos : 0;
    const message = (e as Error).message.replace(/\s*\(\d+:\d+\)$/, '');
    throw new FormulaError(`cannot read the formula: ${message.toLowerCase()}`, [
      pos,
      Math.min(text.length, pos + 1),
    ]);
  }
  const rest = text.slice(expr.end);
  if (rest.trim() !== '') {
    const at = expr.end + (rest.length - rest.trimStart().length);
    throw new FormulaError('the formula goes on after its end: one expression only', [at, text.length]);
  }
  return convert(expr, 0);
}
