/**
 * Nesting depth of a parsed JSON value. JSON.parse accepts a million nested arrays, but
 * JSON.stringify and structuredClone recurse and overflow the stack at a few thousand levels: a
 * document that loaded could then not be saved, shared or undone. Walked iteratively, so the
 * check itself has no depth limit.
 */

/** Whether some object or array inside `value` sits more than `max` levels deep (fast path). */
function exceedsDepth(value: unknown, max: number): boolean {
  const values: unknown[] = [value];
  const depths: number[] = [0];
  while (values.length > 0) {
    const v = values.pop() as object;
    const depth = depths.pop()!;
    if (depth >= max) return true;
    const children = Array.isArray(v) ? v : Object.values(v);
    for (const child of children) {
      if (child !== null && typeof child === 'object') {
        values.push(child);
        depths.push(depth + 1);
      }
    }
  }
  return false;
}

/** The path to the first value nested more than `max` levels deep, or null when there is none. */
export function pathBeyondDepth(value: unknown, max: number): PropertyKey[] | null {
  if (value === null || typeof value !== 'object' || !exceedsDepth(value, max)) return null;
  // Rare: walk again, remembering how each value was reached, to name the place.
  interface Frame {
    readonly v: unknown;
    readonly depth: number;
    readonly key: PropertyKey | null;
    readonly parent: Frame | null;
  }
  const stack: Frame[] = [{ v: value, depth: 0, key: null, parent: null }];
  while (stack.length > 0) {
    const frame = stack.pop()!;
    const { v, depth } = frame;
    if (v === null || typeof v !== 'object') continue;
    if (depth >= max) {
      const path: PropertyKey[] = [];
      for (let f: Frame | null = frame; f !== null && f.key !== null; f = f.parent) path.push(f.key);
      return path.reverse();
    }
    const keys: PropertyKey[] = Array.isArray(v) ? v.map((_, i) => i) : Object.keys(v);
    for (let i = keys.length - 1; i >= 0; i--) {
      const child = (v as Record<PropertyKey, unknown>)[keys[i]];
      stack.push({ v: child, depth: depth + 1, key: keys[i], parent: frame });
    }
  }
  return null;
}
