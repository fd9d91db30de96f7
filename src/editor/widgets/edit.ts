/** How a widget reports an edit: `final` is false while dragging/typing (preview), true at the end (one undo step). */
export type OnEdit<T> = (value: T, final: boolean) => void;

/** Rounds to the step's number of decimals so scrubbing never shows 0.30000000000000004. */
export function roundToStep(v: number, step: number): number {
  const decimals = Math.max(0, Math.min(10, -Math.floor(Math.log10(step))));
  return Number(v.toFixed(decimals));
}

export function clamp(v: number, min?: number, max?: number): number {
  return Math.min(max ?? Number.POSITIVE_INFINITY, Math.max(min ?? Number.NEGATIVE_INFINITY, v));
}

/** Up to 4 decimals, no trailing zeros. */
export const formatNumber = (v: number): string =>
  Number.isFinite(v) ? String(Number(v.toFixed(4))) : String(v);
