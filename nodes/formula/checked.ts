/**
 * Parsed and type-checked formulas by text, for every place that runs one (the Formula node, the
 * seed shape node, the CPU renderer): a drag re-evaluates the graph every frame with the same
 * text, and a render tests a seed shape at every pixel. A mistake is cached as its FormulaError.
 */
import { type Diagnostic, diag } from '../core/diagnostics.ts';
import { type CompiledFormula, compileFormula, typeName } from './compile.ts';
import type { FormulaType, FormulaValue } from './functions.ts';
import { type Formula, FormulaError, parseFormula } from './parse.ts';

export interface CheckedFormula extends CompiledFormula {
  readonly tree: Formula;
}

type Names = Readonly<Record<string, FormulaType>>;
/**
 * Per name table (the tables are module constants), by text: a colour formula is looked up at every
 * pixel, so the lookup must not build a key string.
 */
const caches = new WeakMap<Names, Map<string, CheckedFormula | FormulaError>>();
const CACHE_SIZE = 256;

/** The checked formula for `text` with these names, or the FormulaError that says what is wrong. */
export function checkedFormula(text: string, names: Names): CheckedFormula | FormulaError {
  let cache = caches.get(names);
  if (!cache) {
    cache = new Map();
    caches.set(names, cache);
  }
  const hit = cache.get(text);
  if (hit) return hit;
  let result: CheckedFormula | FormulaError;
  try {
    const tree = parseFormula(text);
    result = { tree, ...compileFormula(tree, names) };
  } catch (e) {
    if (!(e instanceof FormulaError)) throw e;
    result = e;
  }
  if (cache.size >= CACHE_SIZE) cache.delete(cache.keys().next().value!);
  cache.set(text, result);
  return result;
}

/**
 * A colour function's value: the number formula `text` run in `env`, 0 where it does not check or
 * is not finite (the GLSL twin: formula.glsl.ts finiteFormulaFunction).
 */
export function finiteValue(text: string, names: Names, env: object): number {
  const run = numberRun(text, names);
  const v = run ? (run(env as Record<string, FormulaValue>) as number) : 0;
  return Number.isFinite(v) ? v : 0;
}

/** The run of a formula that checks and gives a number, else null (its node reports why). */
export function numberRun(text: string, names: Names): CompiledFormula['run'] | null {
  const f = checkedFormula(text, names);
  return f instanceof FormulaError || f.type !== 'number' ? null : f.run;
}

/** Where in the text: “characters 5–7 (“foo”)”, “character 3 (“+”)”, or “at the end”. */
export function formulaPlace(text: string, [start, end]: readonly [number, number]): string {
  if (start >= text.length) return 'at the end';
  const piece = text.slice(start, Math.max(end, start + 1));
  const shown = piece.length > 24 ? `${piece.slice(0, 23)}…` : piece;
  return end - start > 1
    ? `characters ${start + 1}–${end} (“${shown}”)`
    : `character ${start + 1} (“${shown}”)`;
}

/**
 * A node's formula, checked with `names`, or what the node says when it cannot use it: KF327
 * naming the characters of a formula that does not check, or KF327 for one whose type is not
 * among `accepts` (`needs` says what the node takes). The diagnostic names the param (`param`, as
 * its port) and carries the span, so the node's field underlines the characters at fault.
 */
export function formulaFor(
  nodeId: string,
  text: string,
  names: Readonly<Record<string, FormulaType>>,
  accepts: readonly FormulaType[],
  needs: string,
  param = 'formula',
): { readonly formula: CheckedFormula } | { readonly problem: Diagnostic } {
  const f = checkedFormula(text, names);
  if (f instanceof FormulaError)
    return {
      problem: {
        ...diag('formula', { nodeId, port: param }, f.message, formulaPlace(text, f.span)),
        span: f.span,
      },
    };
  if (!accepts.includes(f.type))
    return {
      problem: {
        ...diag('formula', { nodeId, port: param }, `${needs}, not ${typeName(f.type)}`, 'as a whole'),
        span: [0, text.length],
      },
    };
  return { formula: f };
}
