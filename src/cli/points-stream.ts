/**
 * A points file `[[x, y], …]` read as a stream: bytes are decoded and split into entries as they
 * arrive, and the points come out in batches, so any number of points that fits on disk works in
 * bounded memory. Every problem is one CliError naming the file and, where there is one, the first
 * bad entry. An entry (with the whitespace around it) longer than INPUT_LIMITS.pointEntryChars is
 * refused, so no input — /dev/zero, endless whitespace — makes the reader hold more than that.
 */
import type { Vec3 } from '../../nodes/core/scene-3d.ts';
import type { Vec2 } from '../../nodes/core/values.ts';
import { formatBytes, INPUT_LIMITS } from '../io/input-limits.ts';
import { CliError } from './command.ts';

/** Points per batch handed to the caller, at least (a batch ends with a piece of the file). */
const BATCH = 4096;

const describe = (v: unknown): string => {
  if (Array.isArray(v)) return `an array of ${v.length}`;
  if (v === null) return 'null';
  if (typeof v === 'object') return 'an object';
  const s = JSON.stringify(v) ?? String(v);
  return s.length > 40 ? `${s.slice(0, 37)}...` : s;
};

/** What a JSON value starting with `c` is, for "expected an array …, got …". */
function kindOf(c: string): string | null {
  if (c === '{') return 'an object';
  if (c === '"') return 'a string';
  if (c === '-' || (c >= '0' && c <= '9')) return 'a number';
  if (c === 't' || c === 'f') return 'a boolean';
  if (c === 'n') return 'null';
  return null;
}

const NUMBER = '-?(?:0|[1-9]\\d*)(?:\\.\\d+)?(?:[eE][+-]?\\d+)?';
/** The common entry `[x, y]`, read without JSON.parse (10 M entries: seconds saved). */
const PAIR = new RegExp(`^\\s*\\[\\s*(${NUMBER})\\s*,\\s*(${NUMBER})\\s*\\]\\s*$`);
const isSpace = (c: number) => c === 0x20 || c === 0x0a || c === 0x0d || c === 0x09;

/** What a point of each dimension looks like, for messages. */
const SHAPE = { 2: '[x, y] with two finite numbers', 3: '[x, y, z] with three finite numbers' } as const;
/** Said when an entry has the other dimension's shape: the graph and the points do not match. */
const WRONG_SPACE = {
  2: ' (a point of space: this graph is 2D, it takes [x, y] points)',
  3: ' (a point of the plane: this graph is 3D, it takes [x, y, z] points)',
} as const;

/** One entry's text as a point, or the one-line reason it is not. */
function entryPoint(path: string, index: number, text: string, dimension: 2 | 3): Vec2 | Vec3 {
  if (dimension === 2) {
    const m = PAIR.exec(text);
    if (m) {
      const x = Number(m[1]);
      const y = Number(m[2]);
      if (Number.isFinite(x) && Number.isFinite(y)) return [x, y];
    }
  }
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (e) {
    throw new CliError(`"${path}" is not valid JSON: entry [${index}]: ${(e as Error).message}`);
  }
  const numbers = Array.isArray(value) && value.every((c) => typeof c === 'number' && Number.isFinite(c));
  if (!numbers || (value as unknown[]).length !== dimension) {
    const other = numbers && (value as unknown[]).length === 5 - dimension ? WRONG_SPACE[dimension] : '';
    throw new CliError(`"${path}"[${index}]: expected ${SHAPE[dimension]}, got ${describe(value)}${other}`);
  }
  return value as Vec2 | Vec3;
}

export interface PointsStreamOptions {
  /** Called with the number of bytes read so far, after each piece (for progress). */
  readonly onBytes?: (bytes: number) => void;
  /** Points of the plane, [x, y] (the default), or of space, [x, y, z] (a 3D graph). */
  readonly dimension?: 2 | 3;
}

/**
 * The points of a `[[x, y], …]` file in input order, in batches (what one piece of the file
 * holds, or more). Throws a CliError (after yielding the batches before it) at the first problem.
 */
export function streamPoints(
  path: string,
  chunks: AsyncIterable<Uint8Array>,
  options?: PointsStreamOptions & { readonly dimension?: 2 },
): AsyncGenerator<Vec2[]>;
export function streamPoints(
  path: string,
  chunks: AsyncIterable<Uint8Array>,
  options: PointsStreamOptions & { readonly dimension: 3 },
): AsyncGenerator<Vec3[]>;
export async function* streamPoints(
  path: string,
  chunks: AsyncIterable<Uint8Array>,
  options: PointsStreamOptions = {},
): AsyncGenerator<(Vec2 | Vec3)[]> {
  const dimension = options.dimension ?? 2;
  const decoder = new TextDecoder('utf-8', { fatal: true, ignoreBOM: false });
  const notJson = (why: string) => new CliError(`"${path}" is not valid JSON: ${why}`);
  /** 'start': before "["; 'entry': in or before an entry; 'end': after the closing "]". */
  let state: 'start' | 'entry' | 'end' = 'start';
  let carry = ''; // the unfinished entry from the previous pieces
  let depth = 0; // its scan state: brackets open, inside a string, after a backslash there
  let inString = false;
  let escaped = false;
  let count = 0; // entries finished
  let afterComma = false;
  let batch: (Vec2 | Vec3)[] = [];
  let bytes = 0;
  let blank = 0; // whitespace before "[" or after "]"
  const space = () => {
    if (++blank > INPUT_LIMITS.pointEntryChars)
      throw notJson(`more than ${formatBytes(INPUT_LIMITS.pointEntryChars)} of whitespace outside the array`);
  };

  const scan = (piece: string) => {
    const text = piece;
    let i = 0;
    while (i < text.length) {
      if (state === 'start') {
        const c = text.charCodeAt(i);
        if (isSpace(c)) {
          space();
          i++;
          continue;
        }
        if (text[i] !== '[') {
          const kind = kindOf(text[i]);
          if (kind) throw new CliError(`"${path}": expected an array of [x, y] points, got ${kind}`);
          throw notJson(`it should start with "[", found ${JSON.stringify(text[i])}`);
        }
        state = 'entry';
        i++;
        continue;
      }
      if (state === 'end') {
        if (!isSpace(text.charCodeAt(i)))
          throw notJson(`unexpected ${JSON.stringify(text[i])} after the closing "]"`);
        space();
        i++;
        continue;
      }
      // An entry: up to the "," or "]" outside any string and bracket. Its scan state lives on
      // across pieces, so a piece is scanned once and never joined to the one before.
      const start = i;
      let done = false;
      for (; i < text.length; i++) {
        const c = text.charCodeAt(i);
        if (inString) {
          if (escaped) escaped = false;
          else if (c === 0x5c) escaped = true;
          else if (c === 0x22) inString = false;
          continue;
        }
        if (c === 0x22) inString = true;
        else if (c === 0x5b || c === 0x7b) depth++;
        else if (c === 0x7d || (c === 0x5d && depth > 0)) depth--;
        else if (depth === 0 && (c === 0x2c || c === 0x5d)) {
          done = true;
          break;
        }
        if (depth < 0) throw notJson(`entry [${count}] has an unmatched "}"`);
      }
      const entry = carry + text.slice(start, i);
      if (entry.length > INPUT_LIMITS.pointEntryChars)
        throw new CliError(
          `"${path}": entry [${count}] is longer than ${formatBytes(INPUT_LIMITS.pointEntryChars)}, the limit for one point`,
        );
      if (!done) {
        carry = entry; // finished by a later piece
        return;
      }
      carry = '';
      depth = 0;
      const closing = text[i] === ']';
      i++;
      if (entry.trim() === '') {
        if (closing && count === 0 && !afterComma) {
          state = 'end'; // "[]": no points
          continue;
        }
        throw notJson(`entry [${count}] is empty`);
      }
      batch.push(entryPoint(path, count, entry, dimension));
      count++;
      afterComma = !closing;
      if (closing) state = 'end';
    }
  };

  const decode = (piece?: Uint8Array): string => {
    try {
      return piece ? decoder.decode(piece, { stream: true }) : decoder.decode();
    } catch {
      throw new CliError(`"${path}" is not UTF-8 text: expected a JSON array of [x, y] points`);
    }
  };
  for await (const piece of chunks) {
    bytes += piece.length;
    scan(decode(piece));
    options.onBytes?.(bytes);
    if (batch.length >= BATCH) {
      yield batch;
      batch = [];
    }
  }
  scan(decode());
  if (state === 'start') throw notJson('the file is empty');
  if (state === 'entry') throw notJson(`the file ends before the closing "]" (after ${count} points)`);
  if (batch.length > 0) yield batch;
}
