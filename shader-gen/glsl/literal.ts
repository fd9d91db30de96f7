/**
 * GLSL ES 3.00 literals for baked values. A float literal is the shortest decimal that reads back
 * as the same float64 (JavaScript's `String`), with a `.0` added when it would read as an int; the
 * GLSL compiler then rounds it to the nearest float32, as `Float32Array` does for uniforms, so the
 * baked and the uniform program see the same numbers.
 */

export function floatLiteral(x: number): string {
  if (!Number.isFinite(x)) throw new Error(`cannot write ${x} as a GLSL literal`);
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
