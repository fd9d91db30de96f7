/**
 * Two-generator recipes from Indra's Pearls (docs/math.md "Two-generator recipes"): det-1 matrices
 * a, b with chosen traces. Grandma's and Jørgensen's recipes take tr a = ta and tr b = tb and make
 * the commutator parabolic, tr(a b a⁻¹ b⁻¹) = −2; Riley's takes two parabolics and a complex c.
 */
import { type Complex, cadd, cdiv, cmul, cnear, cscale, csqrt, csub } from './complex.ts';
import { composeMatrices, inverseMatrix, type MobiusMatrix } from './mobius-matrix.ts';

export const RECIPES = ['grandma', 'jorgensen', 'riley'] as const;
export type RecipeName = (typeof RECIPES)[number];

/** The two generators and the trace of their product. */
export interface RecipeGroup {
  readonly a: MobiusMatrix;
  readonly b: MobiusMatrix;
  /** tr(ab). */
  readonly tab: Complex;
}

const I: Complex = [0, 1];
const c = (re: number, im = 0): Complex => [re, im];

/** tr m = a + d. */
export const traceOf = (m: MobiusMatrix): Complex => cadd(m.a, m.d);

/** tr(a b a⁻¹ b⁻¹). */
export const commutatorTrace = (a: MobiusMatrix, b: MobiusMatrix): Complex =>
  traceOf(composeMatrices(composeMatrices(a, b), composeMatrices(inverseMatrix(a), inverseMatrix(b))));

/**
 * The root tab = (ta·tb − √(ta²tb² − 4(ta² + tb²)))/2 of x² − ta·tb·x + ta² + tb² = 0: the trace of
 * ab that makes tr[a, b] = −2 (Fricke: tr[a,b] = ta² + tb² + tab² − ta·tb·tab − 2). The other root
 * gives the mirror-image group.
 */
export function traceAB(ta: Complex, tb: Complex): Complex {
  const p = cmul(ta, tb);
  const disc = csub(cmul(p, p), cscale(cadd(cmul(ta, ta), cmul(tb, tb)), 4));
  return cscale(csub(p, csqrt(disc)), 0.5);
}

/** Whether a complex number is usable as a divisor (not within 1e-12 of 0) and finite. */
const usable = (z: Complex) =>
  Number.isFinite(z[0]) && Number.isFinite(z[1]) && Math.hypot(z[0], z[1]) > 1e-12;

/**
 * Grandma's recipe: with tab as above and z0 = (tab − 2)·tb / (tb·tab − 2ta + 2i·tab),
 *   a = [[ta/2, (ta·tab − 2tb + 4i)/((2tab + 4)·z0)], [(ta·tab − 2tb − 4i)·z0/(2tab − 4), ta/2]],
 *   b = [[(tb − 2i)/2, tb/2], [tb/2, (tb + 2i)/2]].
 * null where a denominator vanishes (tab = ±2, z0 = 0 or its denominator 0).
 */
export function grandmaRecipe(ta: Complex, tb: Complex): RecipeGroup | null {
  const tab = traceAB(ta, tb);
  const zDen = cadd(csub(cmul(tb, tab), cscale(ta, 2)), cmul(c(0, 2), tab));
  if (!usable(zDen)) return null;
  const z0 = cdiv(cmul(csub(tab, c(2)), tb), zDen);
  const plus = cadd(cscale(tab, 2), c(4));
  const minus = csub(cscale(tab, 2), c(4));
  if (!usable(z0) || !usable(plus) || !usable(minus)) return null;
  const tatab = csub(cmul(ta, tab), cscale(tb, 2));
  const half = cscale(ta, 0.5);
  const a: MobiusMatrix = {
    a: half,
    b: cdiv(cadd(tatab, c(0, 4)), cmul(plus, z0)),
    c: cdiv(cmul(csub(tatab, c(0, 4)), z0), minus),
    d: half,
  };
  const b: MobiusMatrix = {
    a: cscale(csub(tb, cmul(c(2), I)), 0.5),
    b: cscale(tb, 0.5),
    c: cscale(tb, 0.5),
    d: cscale(cadd(tb, cmul(c(2), I)), 0.5),
  };
  return { a, b, tab };
}

/**
 * Jørgensen's recipe: with tab as above,
 *   a = [[ta − tb/tab, ta/tab²], [ta, tb/tab]],   b = [[tb − ta/tab, −tb/tab²], [−tb, ta/tab]].
 * det a = (ta·tb·tab − ta² − tb²)/tab² = 1 by tab's equation. null when tab = 0.
 */
export function jorgensenRecipe(ta: Complex, tb: Complex): RecipeGroup | null {
  const tab = traceAB(ta, tb);
  if (!usable(tab)) return null;
  const tab2 = cmul(tab, tab);
  const a: MobiusMatrix = {
    a: csub(ta, cdiv(tb, tab)),
    b: cdiv(ta, tab2),
    c: ta,
    d: cdiv(tb, tab),
  };
  const b: MobiusMatrix = {
    a: csub(tb, cdiv(ta, tab)),
    b: cscale(cdiv(tb, tab2), -1),
    c: cscale(tb, -1),
    d: cdiv(ta, tab),
  };
  return { a, b, tab };
}

/**
 * Riley's recipe: two parabolics, a = [[1, 0], [c, 1]] (fixing 0) and b = [[1, 2], [0, 1]]
 * (z ↦ z + 2, fixing ∞); tr(ab) = 2 + 2c.
 */
export function rileyRecipe(cc: Complex): RecipeGroup {
  const a: MobiusMatrix = { a: c(1), b: c(0), c: cc, d: c(1) };
  const b: MobiusMatrix = { a: c(1), b: c(2), c: c(0), d: c(1) };
  return { a, b, tab: cadd(c(2), cscale(cc, 2)) };
}

/**
 * The Maskit parameter μ (docs/math.md "The Maskit slice") of a group with tr[a, b] = −2 and one
 * generator parabolic (trace ±2): the other trace t gives μ = ±i·t, the sign making Im μ > 0. The
 * traces (t, 2, tr ab) then match Maskit's group up to conjugation (and b ↔ b⁻¹), so its limit set is
 * the Maskit group's, moved by a Möbius map. null when neither is parabolic, or Im μ = 0.
 */
export function maskitParameter(g: RecipeGroup): Complex | null {
  if (!cnear(commutatorTrace(g.a, g.b), c(-2), 1e-7)) return null;
  const ta = traceOf(g.a);
  const tb = traceOf(g.b);
  const parabolic = (t: Complex) => cnear(cmul(t, t), c(4), 1e-9);
  const t = parabolic(tb) ? ta : parabolic(ta) ? tb : null;
  if (!t) return null;
  const mu = cmul(I, t);
  if (Math.abs(mu[1]) < 1e-9) return null;
  return mu[1] > 0 ? mu : cscale(mu, -1);
}
