/**
 * A short JSON-like rendering of any value a document may hold, for messages ("got …"). It is
 * bounded in depth and length, so a 10,000-level nested array or a 10 MB string in a file costs
 * a few characters and never overflows the stack (JSON.stringify does both).
 */

/** Nesting shown before "…" stands in for deeper levels. */
const MAX_DEPTH = 3;

function write(v: unknown, depth: number, budget: number): string {
  if (typeof v === 'string') return JSON.stringify(v.length > budget ? `${v.slice(0, budget)}…` : v);
  if (typeof v !== 'object' || v === null) return String(v);
  if (depth >= MAX_DEPTH) return Array.isArray(v) ? '[…]' : '{…}';
  const parts: string[] = [];
  let used = 2;
  const keys = Array.isArray(v) ? null : Object.keys(v);
  const count = keys ? keys.length : (v as unknown[]).length;
  for (let i = 0; i < count; i++) {
    const key = keys ? keys[i] : null;
    const x = keys ? (v as Record<string, unknown>)[keys[i]] : (v as unknown[])[i];
    if (used > budget) {
      parts.push('…');
      break;
    }
    const text = `${key === null ? '' : `${JSON.stringify(key.slice(0, budget))}:`}${write(x, depth + 1, budget - used)}`;
    parts.push(text);
    used += text.length + 1;
  }
  return Array.isArray(v) ? `[${parts.join(',')}]` : `{${parts.join(',')}}`;
}

/** `v` as (roughly) JSON in at most `max` characters (a longer rendering ends in "..."). */
export function describeValue(v: unknown, max = 60): string {
  const s = write(v, 0, max);
  return s.length > max ? `${s.slice(0, max - 3)}...` : s;
}
