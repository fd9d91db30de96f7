/**
 * GLSL ES 3.00 literals for baked values. A float literal is the shortest decimal that reads back
 * as the same float64 (JavaScript's `String`), with a `.0` added when it would read as an int; the
 * GLSL compiler then rounds it to the nearest float32, as `Float32Array` does for uniforms, so the
 * baked and the uniform program see the same numbers.
 */

/** The largest finite float32: (2 − 2⁻²³)·2¹²⁷. */
export const FLOAT32_MAX = 3.4028234663852886e38;

/**
 * A scene number as the GPU can hold it: values beyond ±FLOAT32_MAX (a derived value such as r² of
 * a huge but finite radius) are clamped to it — compile() already reports them with KF405 — so
 * neither a uniform nor a literal is ever ∞. NaN passes through untouched: it is a bug upstream,
 * which the uniform upload path refuses loudly (src/viewport/uniforms.ts) and a literal cannot hold.
 */
export function gpuFloat(x: number): number {
  return Number.isNaN(x) ? x : Math.max(-FLOAT32_MAX, Math.min(FLOAT32_MAX, x));
}

export function floatLiteral(value: number): string {
  if (Number.isNaN(value)) throw new Error('cannot write NaN as a GLSL literal');
  const x = gpuFloat(value);
  const s = String(x === 0 ? 0 : x); // −0 → "0"
  return /[.e]/.test(s) ? s : `${s}.0`;
}

export function intLiteral(n: number): string {
  if (!Number.isInteger(n)) throw new Error(`${n} is not an integer`);
  return String(n);
}

/** `vecN(a, b, …)` for N = values.length (2–4), or a float literal for one value. */
export function vecLiteral(values: readonly number[]): string {
  if (values.length === 1) return floatLiteral(values[0]);
  return `vec${values.length}(${values.map(floatLiteral).join(', ')})`;
}
