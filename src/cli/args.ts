/**
 * A tiny command-line parser (no dependency): positionals plus options declared once, from which
 * both parsing and the usage text's option list come. Accepts `--name value`, `--name=value`,
 * `-n value`, flags without values, and `--` to end the options.
 */
import { usageError } from './command.ts';

export interface OptionSpec {
  /** Long name without dashes, e.g. "output". */
  readonly long: string;
  /** One-letter alias without the dash, e.g. "o". */
  readonly short?: string;
  /** Placeholder of the value (e.g. "FILE"); absent for a flag. */
  readonly value?: string;
  readonly doc: string;
}

export interface ParsedArgs {
  readonly positionals: readonly string[];
  /** Option values by long name; `true` for a flag that was given. The last occurrence wins. */
  readonly options: Readonly<Record<string, string | true>>;
}

export function parseArgs(args: readonly string[], specs: readonly OptionSpec[]): ParsedArgs {
  const positionals: string[] = [];
  const options: Record<string, string | true> = {};
  const find = (token: string): OptionSpec | undefined =>
    token.startsWith('--')
      ? specs.find((s) => s.long === token.slice(2))
      : specs.find((s) => s.short !== undefined && s.short === token.slice(1));
  for (let i = 0; i < args.length; i++) {
    const arg = args[i];
    if (arg === '--') {
      positionals.push(...args.slice(i + 1));
      break;
    }
    if (!arg.startsWith('-') || arg === '-') {
      positionals.push(arg);
      continue;
    }
    const eq = arg.startsWith('--') ? arg.indexOf('=') : -1;
    const token = eq > 0 ? arg.slice(0, eq) : arg;
    const spec = find(token);
    if (!spec) throw usageError(`unknown option ${token}`);
    if (!spec.value) {
      if (eq > 0) throw usageError(`option --${spec.long} takes no value`);
      options[spec.long] = true;
      continue;
    }
    const value = eq > 0 ? arg.slice(eq + 1) : args[++i];
    if (value === undefined || value === '')
      throw usageError(`option ${token} needs a value (${spec.value})`);
    options[spec.long] = value;
  }
  return { positionals, options };
}

/** The "Options:" block of a usage text, aligned in two columns. */
export function formatOptions(specs: readonly OptionSpec[]): string {
  const heads = specs.map(
    (s) => `${s.short ? `-${s.short}, ` : '    '}--${s.long}${s.value ? ` ${s.value}` : ''}`,
  );
  const width = Math.max(...heads.map((h) => h.length));
  return ['Options:', ...specs.map((s, i) => `  ${heads[i].padEnd(width)}  ${s.doc}`)].join('\n');
}

/** The value of a string option, or undefined when absent. */
export function stringOption(parsed: ParsedArgs, long: string): string | undefined {
  const v = parsed.options[long];
  return typeof v === 'string' ? v : undefined;
}

/** A whole number in [min, max] written in full decimal ("4", not "4.5", "4x" or "1e3"). */
export function parseIntegerOption(long: string, text: string, min: number, max: number): number {
  if (!/^\d+$/.test(text)) throw usageError(`--${long} expects a whole number, got "${text}"`);
  const n = Number(text);
  if (n < min || n > max) throw usageError(`--${long} must be between ${min} and ${max}, got ${n}`);
  return n;
}

/** "WIDTHxHEIGHT" (or a single number for a square), each side in [1, max]. */
export function parseSizeOption(long: string, text: string, max: number): { width: number; height: number } {
  const m = /^(\d+)(?:[x×](\d+))?$/i.exec(text);
  if (!m) throw usageError(`--${long} expects WIDTHxHEIGHT such as 1024x768, got "${text}"`);
  const width = parseIntegerOption(long, m[1], 1, max);
  const height = parseIntegerOption(long, m[2] ?? m[1], 1, max);
  return { width, height };
}

/** Exactly one positional per entry of `names` (used in the message), else a usage error. */
export function expectPositionals(parsed: ParsedArgs, names: readonly string[]): string[] {
  const got = parsed.positionals;
  if (got.length < names.length) throw usageError(`missing ${names.slice(got.length).join(' and ')}`);
  if (got.length > names.length) throw usageError(`unexpected argument "${got[names.length]}"`);
  return [...got];
}
